//! The core's modules import each other without a circle, and its leaves import only leaves.
//!
//! Read from the source: every `crate::NAME` a module's code names (its `use crate::` lines and
//! paths written in place), outside comments and outside its `#[cfg(test)]` tests. A folder
//! module (`check/`) is one module with its files.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::Path;

/// The modules that import no feature module: the lexer's primitives, a word and its number,
/// exact arithmetic, word formats, the modal state, text positions and the rule registry.
const LEAVES: [&str; 8] = [
    "decimal",
    "lex",
    "meaning",
    "modal",
    "rules",
    "text",
    "word",
    "wordformat",
];

type Graph = BTreeMap<String, BTreeSet<String>>;

/// The code of a file without its comments and its `#[cfg(test)]` module.
fn code(text: &str) -> String {
    let body = match text.find("#[cfg(test)]\nmod tests") {
        Some(at) => &text[..at],
        None => text,
    };
    body.lines()
        .map(|line| line.find("//").map_or(line, |at| &line[..at]))
        .collect::<Vec<_>>()
        .join("\n")
}

/// The modules named as `crate::NAME` in `code`.
fn imports(code: &str) -> BTreeSet<String> {
    let mut found = BTreeSet::new();
    let mut rest = code;
    while let Some(at) = rest.find("crate::") {
        let after = &rest[at + "crate::".len()..];
        let name: String = after
            .chars()
            .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
            .collect();
        // `use crate::{a, b}` names several at once
        if name.is_empty() && after.starts_with('{') {
            let inner = &after[1..after.find('}').unwrap_or(after.len())];
            for part in inner.split(',') {
                let part = part.trim();
                let end = part.find("::").unwrap_or(part.len());
                if !part.is_empty() {
                    found.insert(part[..end].to_string());
                }
            }
        } else if !name.is_empty() {
            found.insert(name);
        }
        rest = after;
    }
    found
}

/// The module graph of the crate's `src`, by reading its files.
fn graph(src: &Path) -> Graph {
    let mut graph = Graph::new();
    for entry in fs::read_dir(src).expect("the crate's src folder") {
        let path = entry.expect("a directory entry").path();
        let (module, files) = if path.is_dir() {
            let files = fs::read_dir(&path)
                .expect("a module folder")
                .map(|e| e.expect("a directory entry").path())
                .filter(|p| p.extension().is_some_and(|e| e == "rs"))
                .collect::<Vec<_>>();
            (
                path.file_name().unwrap().to_string_lossy().into_owned(),
                files,
            )
        } else if path.extension().is_some_and(|e| e == "rs") {
            (
                path.file_stem().unwrap().to_string_lossy().into_owned(),
                vec![path.clone()],
            )
        } else {
            continue;
        };
        if module == "lib" {
            continue; // the crate root declares every module and re-exports
        }
        let edges = graph.entry(module.clone()).or_default();
        for file in files {
            let text = fs::read_to_string(&file).expect("a source file");
            for name in imports(&code(&text)) {
                if name != module {
                    edges.insert(name);
                }
            }
        }
    }
    graph
}

/// A circle of modules in `graph`, if there is one (depth first, by colour).
fn circle(graph: &Graph) -> Option<Vec<String>> {
    fn visit(
        node: &str,
        graph: &Graph,
        state: &mut BTreeMap<String, u8>,
        stack: &mut Vec<String>,
    ) -> Option<Vec<String>> {
        state.insert(node.to_string(), 1);
        stack.push(node.to_string());
        for next in graph.get(node).into_iter().flatten() {
            match state.get(next.as_str()).copied().unwrap_or(0) {
                1 => {
                    let from = stack.iter().position(|n| n == next).unwrap();
                    let mut found = stack[from..].to_vec();
                    found.push(next.clone());
                    return Some(found);
                }
                0 => {
                    if let Some(found) = visit(next, graph, state, stack) {
                        return Some(found);
                    }
                }
                _ => {}
            }
        }
        stack.pop();
        state.insert(node.to_string(), 2);
        None
    }
    let mut state = BTreeMap::new();
    for node in graph.keys() {
        if state.get(node.as_str()).copied().unwrap_or(0) == 0 {
            if let Some(found) = visit(node, graph, &mut state, &mut Vec::new()) {
                return Some(found);
            }
        }
    }
    None
}

fn core_graph() -> Graph {
    graph(&Path::new(env!("CARGO_MANIFEST_DIR")).join("src"))
}

#[test]
fn the_modules_import_each_other_without_a_circle() {
    let graph = core_graph();
    // the reading itself: edges that are known to be there are found
    assert!(graph["check"].contains("word") && graph["check"].contains("modal"));
    assert!(graph["tokenizer"].contains("statement") && graph["statement"].contains("expr"));
    assert_eq!(circle(&graph), None, "{graph:#?}");
    // a name of the crate root (`crate::Family`) would hide its module's edge
    for (module, edges) in &graph {
        let unknown: Vec<_> = edges.iter().filter(|m| !graph.contains_key(*m)).collect();
        assert!(
            unknown.is_empty(),
            "{module} names {unknown:?}, not modules"
        );
    }
}

#[test]
fn the_leaves_import_only_leaves() {
    let graph = core_graph();
    for leaf in LEAVES {
        let edges = graph
            .get(leaf)
            .unwrap_or_else(|| panic!("no module {leaf}"));
        let others: Vec<_> = edges
            .iter()
            .filter(|m| !LEAVES.contains(&m.as_str()))
            .collect();
        assert!(others.is_empty(), "{leaf} imports {others:?}");
    }
}

#[test]
fn the_readers_do_not_import_the_checker() {
    let graph = core_graph();
    for reader in ["ncread", "ncdiff", "convert", "restart"] {
        assert!(
            !graph[reader].contains("check"),
            "{reader} imports check: {:?}",
            graph[reader]
        );
    }
    assert!(
        !graph["ncdiff"].contains("convert"),
        "{:?}",
        graph["ncdiff"]
    );
}

#[test]
fn a_circle_is_found_where_there_is_one() {
    let edges = |pairs: &[(&str, &str)]| {
        let mut g = Graph::new();
        for (a, b) in pairs {
            g.entry(a.to_string()).or_default().insert(b.to_string());
            g.entry(b.to_string()).or_default();
        }
        g
    };
    let found = circle(&edges(&[("a", "b"), ("b", "c"), ("c", "a"), ("c", "d")]));
    assert_eq!(found.map(|c| c.len()), Some(4));
    assert_eq!(circle(&edges(&[("a", "b"), ("a", "c"), ("b", "c")])), None);
}

#[test]
fn imports_are_read_from_code_not_comments_nor_tests() {
    let text = "//! see [`crate::check`]\nuse crate::{lex::Token, word};\nfn f() { crate::text::column(b\"\", 0); } // crate::ncread\n#[cfg(test)]\nmod tests {\n    use crate::convert;\n}\n";
    let found = imports(&code(text));
    let expected: BTreeSet<String> = ["lex", "word", "text"]
        .iter()
        .map(|s| s.to_string())
        .collect();
    assert_eq!(found, expected);
}
