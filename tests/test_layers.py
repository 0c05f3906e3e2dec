"""The Python packages are layers: formats, then postproc, then dnc, then tapegate, each
importing only the ones before it, and no module imports one that imports it back, at the top
of a file or inside a function (docs/architecture: the layers)."""

from __future__ import annotations

import ast
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
LAYERS = ("formats", "postproc", "dnc", "tapegate")
# formats.diff still builds its reader's configuration with postproc.state.core_config: the
# profile-to-core spec of issue 31 replaces it (the one import allowed upward until then).
KNOWN_UPWARD = {("formats.diff", "postproc.state")}


def import_graph() -> dict[str, set[str]]:
    """Module -> the package modules it imports, anywhere in its file."""
    modules: dict[str, Path] = {}
    for package in LAYERS:
        for path in (ROOT / package).rglob("*.py"):
            name = ".".join(path.relative_to(ROOT).with_suffix("").parts)
            modules[name.removesuffix(".__init__")] = path
    graph: dict[str, set[str]] = {name: set() for name in modules}
    for name, path in modules.items():
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
                targets = [node.module, *(f"{node.module}.{a.name}" for a in node.names)]
            elif isinstance(node, ast.Import):
                targets = [a.name for a in node.names]
            else:
                continue
            graph[name].update(t for t in targets if t in modules and t != name)
    return graph


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components of more than one module (Tarjan)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    found: list[list[str]] = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        for w in graph[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return found


def test_no_module_imports_one_that_imports_it_back() -> None:
    graph = import_graph()
    assert "formats.verify" in graph["formats.convert"]  # the walk sees imports
    assert cycles(graph) == []


def test_each_layer_imports_only_the_layers_before_it() -> None:
    upward = {(module, target) for module, targets in import_graph().items()
              for target in targets
              if LAYERS.index(target.split(".")[0]) > LAYERS.index(module.split(".")[0])}
    assert upward <= KNOWN_UPWARD


def test_the_cycle_finder_finds_a_cycle() -> None:
    assert cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]
