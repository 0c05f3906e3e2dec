"""The ``tapegate`` command line: options in, library calls, results out -- no work of its own.

Every user error (:class:`formats.errors.TapegateError`) is printed as one located line on
stderr, never as a traceback. Exit codes: 0 done, 1 the input is bad (parse, tape, conversion or
check findings), 2 usage error or unreadable file.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Callable, Iterable, Iterator, Sequence
from functools import wraps
from pathlib import Path
from typing import TYPE_CHECKING, Any, TypeVar

import click

from formats.errors import OutputError, ProfileError, TapegateError
from formats.profile import NEUTRAL, Profile, builtin_names, builtin_text, load_profile
from formats.source import Source
from formats.wordformat import Rounding, Zeros
from postproc.rules import RULES, SEVERITY_RANK

# A command imports what only it uses (the parser's streams, the printer, tape codes, the
# converter, lark's classification grammar), so that a short check starts no more than it needs.
if TYPE_CHECKING:
    from formats.convert import ConvertOptions, ConvertStats
    from formats.parser import BadBlock
    from postproc.check import CheckStats

F = TypeVar("F", bound=Callable[..., Any])


class UsageProblem(click.ClickException):
    exit_code = 2


def user_errors(func: F) -> F:
    """Turn a TapegateError into a located message and exit code 1 (2 for unreadable files)."""

    @wraps(func)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        try:
            return func(*args, **kwargs)
        except (ProfileError, OutputError) as exc:
            click.echo(f"tapegate: {exc.message if isinstance(exc, OutputError) else exc}",
                       err=True)
            sys.exit(2)
        except TapegateError as exc:
            click.echo(str(exc), err=True)
            sys.exit(1)
        except (FileNotFoundError, IsADirectoryError, PermissionError) as exc:
            click.echo(f"tapegate: cannot read {exc.filename}: {exc.strerror}", err=True)
            sys.exit(2)
        except UnicodeDecodeError as exc:  # a binary file where a text file was wanted
            click.echo(f"tapegate: cannot read a file given: not UTF-8 text ({exc.reason} at "
                       f"byte {exc.start})", err=True)
            sys.exit(2)
        except BrokenPipeError:
            sys.exit(0)

    return wrapper  # type: ignore[return-value]


_SPOOLED: list[Any] = []  # standard input's temporary copies, alive while the command runs


def readable(name: str) -> str:
    """The path a file argument is read from: ``-`` is standard input, copied once to a
    temporary file (a program is read more than once: detection, parameters, conversion)."""
    if name != "-":
        return name
    import shutil
    import tempfile

    spool = tempfile.NamedTemporaryFile(prefix="tapegate-stdin-", suffix=".nc")  # noqa: SIM115
    shutil.copyfileobj(sys.stdin.buffer, spool)
    spool.flush()
    _SPOOLED.append(spool)
    return spool.name


def plural(count: int, noun: str, many: str | None = None) -> str:
    """``1 comment``, ``2 comments``, ``1 match``, ``2 matches``."""
    return f"{count} {noun if count == 1 else many or noun + 's'}"


def shown(name: str) -> str:
    """A file argument as messages name it."""
    return "<stdin>" if name == "-" else name


def shown_output(name: str) -> str:
    return "<stdout>" if name == "-" else name


def write_stream(output: str, pieces: Iterable[bytes]) -> int:
    """``-o FILE`` written atomically piece by piece, or ``-o -`` to standard output; the bytes
    written."""
    size = 0
    if output == "-":
        sys.stdout.flush()
        for piece in pieces:
            sys.stdout.buffer.write(piece)
            size += len(piece)
        sys.stdout.buffer.flush()
        return size
    from formats.files import PendingFile

    target = Path(output)
    with PendingFile(target.parent, target.name) as pending:
        for piece in pieces:
            pending.write(piece)
        pending.commit(target, overwrite=True)
        return pending.size


def profile_option() -> Callable[[F], F]:
    """``--profile``/``-p``, optional on every command: without it the program is read with the
    neutral profile, adjusted to what can be detected in the program, and stderr says so."""
    return click.option(
        "--profile", "-p", "profile",
        help="Machine profile: a built-in name (see `tapegate profiles`) or a .toml file "
             "(default: the neutral profile, with the units codes and decimal style detected "
             "in the program).")


def get_profile(name: str | None, file: str | None = None) -> Profile:
    """The named profile; without a name, the neutral one, adjusted to what ``file`` shows."""
    if name is not None:
        return load_profile(name)
    notes = ["no --profile: the neutral profile (no machine limits, common characters accepted)"]
    profile = NEUTRAL
    if file is not None and file != "-":
        from formats.convert import detect_source

        try:
            head = next(iter(Source(file).chunks()), "")
        except OSError:
            head = ""  # the command itself reports an unreadable file
        profile, detected = detect_source(head[:1 << 20])
        notes += [note.removeprefix("source: ") for note in detected]
    click.echo("tapegate: " + "; ".join(notes), err=True)
    return profile


class LazyGroup(click.Group):
    """A group whose serial and gateway commands are imported when they are used (click's
    documented pattern for lazy subcommands), so ``parse``, ``check`` and ``convert`` do not load
    pyserial, pymodbus and the DNC layer."""

    LAZY = {
        "send": "tapegate.serial_cli:send",
        "receive": "tapegate.serial_cli:receive",
        "journal": "tapegate.serial_cli:journal_command",
        "emulate": "tapegate.serial_cli:emulate",
        "serve": "tapegate.serve_cli:serve",
    }

    def list_commands(self, ctx: click.Context) -> list[str]:
        return sorted([*super().list_commands(ctx), *self.LAZY])

    def get_command(self, ctx: click.Context, cmd_name: str) -> click.Command | None:
        target = self.LAZY.get(cmd_name)
        if target is None:
            return super().get_command(ctx, cmd_name)
        import importlib

        module, name = target.split(":")
        command = getattr(importlib.import_module(module), name)
        assert isinstance(command, click.Command)
        return command


@click.group(cls=LazyGroup, context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(package_name="tapegate")
def main() -> None:
    """tapegate: convert, check and drip-feed ISO 6983-1 NC programs."""


# ---------------------------------------------------------------------------------------------
# parse


@main.command(short_help="Read a program (text or tape image) into blocks of words.")
@click.argument("file", type=click.Path(dir_okay=False))
@profile_option()
@click.option("--json", "as_json", is_flag=True, help="One JSON object per block (JSON Lines).")
@click.option("--summary", is_flag=True, help="Counts only (blocks, words, comments, speed).")
@click.option("--reprint", is_flag=True, help="Print the program back from the parsed model.")
@user_errors
def parse(file: str, profile: str | None, as_json: bool, summary: bool, reprint: bool) -> None:
    """Parse FILE (text or ISO/EIA tape image, - for standard input) into blocks of words."""
    import json
    import time

    from formats.parser import BadBlock, count_blocks, parse_stream
    from formats.printer import print_blocks

    path, file = readable(file), shown(file)
    prof = get_profile(profile, path)
    source = Source(path)
    # A block the profile cannot read is kept as it is (and reported on stderr): the reprint is
    # the whole file, byte for byte, and the JSON has every block.
    unreadable: list[BadBlock] = []

    def noted(blocks: Any) -> Any:
        for block in blocks:
            if isinstance(block, BadBlock):
                unreadable.append(block)
            yield block

    blocks = noted(parse_stream(source.chunks(), prof.dialect, file=file, errors="collect"))
    out = sys.stdout
    if reprint:
        sys.stdout.flush()
        raw = sys.stdout.buffer
        for text in print_blocks(blocks):
            raw.write(text.encode("utf-8", errors="surrogateescape"))
        raw.flush()
    elif as_json:
        for block in blocks:
            out.write(json.dumps(block_json(block, prof), ensure_ascii=False) + "\n")
    else:
        start = time.perf_counter()
        n_blocks, n_words, n_comments = count_blocks(source.chunks(), prof.dialect, file=file)
        elapsed = time.perf_counter() - start
        rate = n_blocks / elapsed if elapsed > 0 else 0.0
        click.echo(f"{file}: {plural(n_blocks, 'block')}, {plural(n_words, 'word')}, "
                   f"{plural(n_comments, 'comment')} ({source.kind}) in {elapsed:.3f} s, "
                   f"{rate:,.0f} blocks/s")
        if not summary:
            click.echo("(use --json for the blocks, --reprint for the text)")
    for bad in unreadable:
        click.echo(str(bad.error), err=True)
    for issue in source.issues:
        click.echo(f"{file}:{issue.line}:{issue.column}: tape {issue.message()} "
                   f"at byte {issue.offset}", err=True)
    if source.issues or unreadable:
        sys.exit(1)


def block_json(block: Any, prof: Profile) -> dict[str, Any]:
    words = []
    for w in block.word_objects():
        item: dict[str, Any] = {"address": w.address, "column": w.column}
        if w.index:
            item["index"] = w.index
        if w.expression:
            item["expression"] = w.expression
        else:
            item["sign"] = w.sign
            item["number"] = w.number
            try:
                item["value"] = str(prof.value(w.token))
            except TapegateError as exc:
                item["error"] = exc.message
        words.append(item)
    result: dict[str, Any] = {"line": block.line, "text": block.text, "words": words}
    if block.skip:
        result["skip"] = block.skip
    if block.comments:
        result["comments"] = [{"column": c, "text": t} for c, t in block.comments]
    if block.percent:
        result["percent"] = True
        result["ident"] = block.info.ident
    from formats.parser import BadBlock

    if isinstance(block, BadBlock):
        result["error"] = str(block.error)
    return result


# ---------------------------------------------------------------------------------------------
# convert


@main.command(short_help="Convert programs to another machine's format, exactly.")
@click.argument("inputs", nargs=-1, required=True)
@click.option("-o", "--output", type=click.Path(dir_okay=False),
              help="Output file (one input file only).")
@click.option("--out-dir", type=click.Path(file_okay=False),
              help="Output folder; directories keep their relative layout.")
@click.option("--to", "to_profile", required=True, help="Target machine profile.")
@click.option("--from", "from_profile", default=None,
              help="Source machine profile (default: detect decimal points and units codes).")
@click.option("--from-decimal", type=click.Choice(["explicit", "implicit", "increments"]),
              default=None, help="Read the source's words without a decimal point as whole "
              "numbers (explicit), by its word formats (implicit) or as least increments "
              "(increments: X10000 = 10.000, as a Fanuc reads it).")
@click.option("--from-zeros", type=click.Choice(["leading", "trailing", "none"]), default=None,
              help="Which zeros the source's implicit-decimal words omit.")
@click.option("--decimal", type=click.Choice(["explicit", "implicit"]), default=None,
              help="Override the target's decimal sign style.")
@click.option("--zeros", type=click.Choice(["leading", "trailing", "none"]), default=None,
              help="Override which zeros implicit-decimal words omit.")
@click.option("--units", type=click.Choice(["metric", "inch"]), default=None,
              help="Convert to these units (default: keep the program's units).")
@click.option("--eob", type=click.Choice(["lf", "crlf"]), default=None,
              help="Rewrite every end of block (default: keep as written).")
@click.option("--spacing", type=click.Choice(["keep", "remove", "insert"]), default="keep",
              show_default=True, help="Spaces between words.")
@click.option("--round", "rounding", type=click.Choice([r.value for r in Rounding]),
              default="half-even", show_default=True,
              help="Rounding to the target resolution; 'error' refuses any rounding.")
@click.option("--allow-unconverted", is_flag=True,
              help="Leave parameters and P/Q/R words whose units cannot be proved as written.")
@click.option("--jobs", "-j", type=click.IntRange(1), default=None,
              help="Files converted in parallel (default: the CPU count).")
@click.option("--verify", is_flag=True, help="Read the output back and prove every value.")
@click.option("--dry-run", is_flag=True, help="Convert and report, write nothing.")
@click.option("--force", is_flag=True, help="Overwrite existing outputs.")
@user_errors
def convert(inputs: tuple[str, ...], output: str | None, out_dir: str | None, to_profile: str,
            from_profile: str | None, from_decimal: str | None, from_zeros: str | None,
            decimal: str | None, zeros: str | None,
            units: str | None, eob: str | None, spacing: str, rounding: str,
            allow_unconverted: bool, jobs: int | None, verify: bool, dry_run: bool,
            force: bool) -> None:
    """Convert programs to another machine's format: decimal style, zeros, units, exactly.

    INPUTS are files, folders or patterns; - reads standard input, and -o - writes the result
    to standard output (the summary then goes to standard error)."""
    from formats.convert import ConvertOptions  # (only this command needs the converter)

    names: dict[str, str] = {}
    if "-" in inputs:
        if len(inputs) != 1:
            raise UsageProblem("- (standard input) is the only input when it is given")
        inputs = (readable("-"),)
        names[inputs[0]] = "<stdin>"
    to_stdout = output == "-"
    if to_stdout:
        import tempfile

        output = str(Path(tempfile.mkdtemp(prefix="tapegate-")) / "out.nc")
    if out_dir and not dry_run:  # a file where the folder (or one above it) would be
        there = next((p for p in (Path(out_dir), *Path(out_dir).parents) if p.exists()), None)
        if there is not None and not there.is_dir():
            raise OutputError(f"cannot write {out_dir}: {there} is not a folder")
    jobs_list = batch_jobs(inputs, output, out_dir, dry_run)
    options = ConvertOptions(
        target=load_profile(to_profile),
        source=load_profile(from_profile) if from_profile else None,
        decimal=decimal, zeros=Zeros(zeros) if zeros else None, units=units, eob=eob,
        rounding=Rounding(rounding), spacing=spacing, allow_unconverted=allow_unconverted,
        from_decimal=from_decimal, from_zeros=Zeros(from_zeros) if from_zeros else None)
    from tapegate.workers import default_jobs

    results = run_batch(jobs_list, options, jobs=jobs or default_jobs(), overwrite=force,
                        verify=verify, names=names, make_folders=out_dir is not None)
    if to_stdout and output is not None:
        done = Path(output)
        if done.exists():
            from formats.parser import read_chunks

            write_stream("-", read_chunks(str(done)))
            done.unlink()
        done.parent.rmdir()
    rows = []
    failed = 0
    for stats in results:
        letter, worst = stats.largest_rounding()
        if stats.error:
            failed += 1
            click.echo(stats.error, err=True)
        for note in stats.notes:
            click.echo(f"{stats.file}: {note}", err=True)
        result = "FAILED" if stats.error else ("verified" if stats.verified else "ok")
        rows.append((stats.file, str(stats.blocks), str(stats.changed),
                     f"{letter} {worst}" if letter else "0", result))
    total_blocks = sum(s.blocks for s in results)
    total_changed = sum(s.changed for s in results)
    if len(rows) > 1 or failed or not sys.stdout.isatty():
        rows.append((f"total: {len(results)} files", str(total_blocks), str(total_changed), "",
                     f"{failed} failed"))
    click.echo(table(("file", "blocks", "words changed", "largest rounding", "result"), rows),
               err=to_stdout)
    if dry_run:
        click.echo("dry run: nothing written", err=to_stdout)
    if failed:
        sys.exit(1)


def batch_jobs(inputs: Sequence[str], output: str | None, out_dir: str | None,
               dry_run: bool) -> list[tuple[str, str | None]]:
    """(input file, output file or None) for every file named by the inputs."""
    import glob

    files: list[tuple[Path, Path]] = []  # (file, path relative to the output folder)
    for name in inputs:
        path = Path(name)
        if path.is_dir():
            for found in sorted(path.rglob("*")):
                if found.is_file() and not any(p.startswith(".") for p in
                                               found.relative_to(path).parts):
                    files.append((found, found.relative_to(path)))
        elif path.exists():
            files.append((path, Path(path.name)))
        else:
            matches = sorted(Path(m) for m in glob.glob(name, recursive=True))
            matches = [m for m in matches if m.is_file()]
            if not matches:
                raise UsageProblem(f"no such file or directory: {name}")
            files.extend((m, Path(m.name)) for m in matches)
    if output and (len(files) != 1 or Path(inputs[0]).is_dir()):
        raise UsageProblem("-o names one output file; use --out-dir for several inputs")
    if output and out_dir:
        raise UsageProblem("give -o or --out-dir, not both")
    if not (output or out_dir or dry_run):
        raise UsageProblem("say where to write: -o FILE, --out-dir DIR, or --dry-run")
    jobs: list[tuple[str, str | None]] = []
    seen: set[Path] = set()
    for path, relative in files:
        if dry_run:
            target = None
        elif output:
            target = Path(output)
        else:
            target = Path(out_dir or ".") / relative
        if target is not None:
            if target.resolve() == path.resolve():
                raise UsageProblem(f"{path}: the output would replace the input")
            if target in seen:
                raise UsageProblem(f"two inputs would both be written to {target}")
            seen.add(target)
        jobs.append((str(path), str(target) if target else None))
    return jobs


def _convert_one(job: tuple[str, str | None, str]) -> ConvertStats:
    from formats.convert import ConvertStats, convert_file
    from tapegate.workers import shared

    path, output, name = job
    options, overwrite, verify, make_folder = shared()
    try:
        return convert_file(path, output, options, overwrite=overwrite, verify=verify,
                            display=name, make_folder=make_folder)
    except TapegateError as exc:
        return ConvertStats(file=name, output=output or "", error=str(exc.located(file=name)))
    except OSError as exc:
        return ConvertStats(file=name, output=output or "",
                            error=f"{name}: {exc.strerror or exc}")


def run_batch(jobs_list: list[tuple[str, str | None]], options: ConvertOptions, *, jobs: int,
              overwrite: bool, verify: bool, names: dict[str, str] | None = None,
              make_folders: bool = False) -> list[ConvertStats]:
    """Convert every file (in ``jobs`` processes), with a progress bar on a terminal;
    ``make_folders`` creates the output folders (the layout under --out-dir); a folder that
    ``-o`` names must exist, as for every command."""
    names = names or {}
    from tapegate.workers import ordered_map

    work = [(path, out, names.get(path, path)) for path, out in jobs_list]
    settings = (options, overwrite, verify, make_folders)  # given to each worker once
    if len(work) == 1:  # one file: no progress bar, no pool, nothing more to start
        return list(ordered_map(_convert_one, work, 1, shared=settings))
    show = sys.stderr.isatty()
    from tqdm import tqdm

    results = []
    with tqdm(total=len(work), unit="file", disable=not show, file=sys.stderr) as bar:
        for stats in ordered_map(_convert_one, work, jobs, shared=settings):  # in order
            results.append(stats)
            bar.update()
    return results


# ---------------------------------------------------------------------------------------------
# check and plot


def _ids(values: tuple[str, ...]) -> list[str]:
    ids = [v.strip().upper() for item in values for v in item.split(",") if v.strip()]
    for rule in ids:
        if not any(r.startswith(rule) for r in RULES):
            raise UsageProblem(f"no rule {rule}; see docs/rules.md")
    return ids


@main.command(short_help="Check programs against a machine profile.")
@click.argument("files", nargs=-1, required=True, type=click.Path())
@profile_option()
@click.option("--format", "fmt", type=click.Choice(["text", "json", "jsonl", "sarif"]),
              default="text", show_default=True,
              help="jsonl: JSON Lines, one finding per line.")
@click.option("--select", multiple=True, help="Only these rule IDs or prefixes (TG4,TG601).")
@click.option("--ignore", multiple=True, help="Skip these rule IDs or prefixes.")
@click.option("--fail-on", type=click.Choice(["error", "warning"]), default="error",
              show_default=True, help="Exit 1 on findings of this severity or worse.")
@click.option("--stats", "show_stats", is_flag=True,
              help="Bounding box, path lengths, cycle time, tools.")
@click.option("--jobs", "-j", type=click.IntRange(1), default=None,
              help="Files checked in parallel (default: the CPU count).")
def check(files: tuple[str, ...], profile: str | None, fmt: str, select: tuple[str, ...],
          ignore: tuple[str, ...], fail_on: str, show_stats: bool, jobs: int | None) -> None:
    """Check programs (text or ISO/EIA tape images; a folder: every file in it) against a
    machine profile."""
    from postproc import report
    from postproc.check import iter_check_file, profile_named
    from tapegate.workers import default_jobs, input_files

    given, files = files, tuple(input_files(files))
    if not files:
        raise UsageProblem(f"no file to check in {', '.join(given)}")
    parallel = (jobs or default_jobs()) > 1 and len(files) > 1

    try:
        paths = {name: readable(name) for name in files}
        prof = profile_named(profile) if profile else get_profile(None, paths[files[0]])
        selected, ignored = _ids(select), _ids(ignore)
    except ProfileError as exc:
        click.echo(f"tapegate: {exc}", err=True)
        sys.exit(2)
    # Every format streams: a finding is written as it is found and only counted (for the
    # summary and the exit code), so memory does not grow with the number of findings.
    counts = dict.fromkeys(SEVERITY_RANK, 0)
    stats: dict[str, CheckStats] = {}
    out = sys.stdout
    writer = (report.JsonReport(out) if fmt == "json" else
              report.JsonLinesReport(out) if fmt == "jsonl" else
              report.SarifReport(out) if fmt == "sarif" else None)
    unreadable = 0
    try:
        for name in () if parallel else files:
            try:
                checker, found = iter_check_file(paths[name], prof, display=shown(name),
                                                 select=selected, ignore=ignored)
                for finding in found:
                    counts[finding.severity] += 1
                    if writer is None:
                        click.echo(str(finding))
                    else:
                        writer.add(finding)
            except BrokenPipeError:  # the output closed: not a file that cannot be read
                raise
            except OSError as exc:
                click.echo(f"tapegate: cannot read {name}: {exc.strerror or exc}", err=True)
                unreadable += 1
                continue
            except TapegateError as exc:  # e.g. not an NC program at all
                click.echo(str(exc.located(file=name)), err=True)
                unreadable += 1
                continue
            stats[name] = checker.stats
        if parallel:  # the same, file by file in worker processes (tapegate.workers)
            from tapegate.workers import check_files

            items = [(paths[name], shown(name)) for name in files]
            for done, name in zip(check_files(items, prof, fmt=fmt, select=selected,
                                              ignore=ignored, jobs=jobs or default_jobs(),
                                              writer=writer, out=out), files, strict=True):
                for severity, n in done.counts.items():
                    counts[severity] += n
                if done.error:
                    click.echo(done.error, err=True)
                    unreadable += 1
                elif done.stats is not None:
                    stats[name] = done.stats
        if isinstance(writer, report.JsonReport | report.JsonLinesReport):
            writer.close(stats if show_stats else None)
        elif isinstance(writer, report.SarifReport):
            writer.close()
        else:
            if show_stats:
                for name, s in stats.items():
                    click.echo(report.stats_text(name, s), nl=False)
            out.flush()
            checked = plural(len(files) - unreadable, "file")
            not_read = f" ({unreadable} not read)" if unreadable else ""
            click.echo(f"{checked} checked{not_read}: {plural(counts['error'], 'error')}, "
                       f"{plural(counts['warning'], 'warning')}, "
                       f"{plural(counts['info'], 'note')}", err=True)
    except BrokenPipeError:
        # The reader stopped reading (``| head``): stop at once and quietly, exit 0 as every
        # command does (user_errors) -- no traceback, no message, and no exit code that would
        # depend on how far the check had come when the pipe closed.
        _silence_stdout()
        sys.exit(0)
    sys.exit(_check_exit_code(counts, bool(unreadable), fail_on))


def _check_exit_code(counts: dict[str, int], unreadable: bool, fail_on: str) -> int:
    if unreadable:
        return 2
    worst_found = max((SEVERITY_RANK[k] for k, n in counts.items() if n), default=-1)
    return 1 if worst_found >= SEVERITY_RANK[fail_on] else 0


def _silence_stdout() -> None:
    """Point stdout at /dev/null, so that what is still buffered for a closed pipe cannot fail
    again when Python flushes it at exit (the recipe of the ``signal`` module's documentation)."""
    try:
        fd = sys.stdout.fileno()
    except (AttributeError, OSError, ValueError):  # not a real file (a test's capture)
        return
    devnull = os.open(os.devnull, os.O_WRONLY)
    try:
        os.dup2(devnull, fd)
    finally:
        os.close(devnull)


# The rules of a block that cannot be read (characters, statements, tape codes): a file of only
# these is no program to draw.
READING_RULES = frozenset({"TG100", "TG101", "TG120", "TG121", "TG125", "TG701", "TG702"})

@main.command(short_help="Draw the tool path, with the findings marked.")
@click.argument("file", type=click.Path(dir_okay=False))
@profile_option()
@click.option("-o", "--output", required=True, type=click.Path(dir_okay=False),
              help="Image file: .svg or .png.")
@click.option("--view", type=click.Choice(["xy", "xz", "yz", "iso"]), default=None,
              help="The plane drawn  [default: xy; xz on a lathe, Z across and X up]")
@click.option("--findings/--no-findings", default=True, show_default=True,
              help="Mark the findings (one marker set and legend entry per rule).")
@user_errors
def plot(file: str, profile: str | None, output: str, view: str | None,
         findings: bool) -> None:
    """Draw the tool path: rapids dashed, feeds solid, true arcs, findings marked."""
    if Path(output).suffix.lower() not in (".svg", ".png"):
        raise UsageProblem("the output must end in .svg or .png")
    folder = Path(output).resolve().parent
    if not folder.is_dir():  # one rule: a missing folder is no output
        raise OutputError(f"cannot write {output}: "
                          + (f"{folder} is not a folder" if folder.exists() else "no such folder"))
    from postproc.check import profile_named

    try:
        from postproc.plot import backplot_file, default_view
        from postproc.plot import plot as draw
    except ImportError:
        raise UsageProblem("plot needs matplotlib, the optional 'plot' extra: "
                           "pip install 'tapegate[plot]'") from None

    prof = profile_named(profile) if profile else get_profile(None, file)
    view = view or default_view(prof)
    bp = backplot_file(file, prof)
    marked = draw(bp, output, view=view, title=f"{file} ({view})", findings=findings)
    impossible = sum(m.impossible for m in bp.moves)
    arcs = sum(m.arc for m in bp.moves) - impossible  # as --stats counts them: chords are none
    total = len(bp.findings)
    shown = (f"{total} findings not shown" if not findings
             else f"{marked} findings marked" if marked == total
             else f"{marked} of {total} findings marked (the rest have no position)")
    click.echo(f"{output}: {len(bp.moves)} moves, {shown}; {plural(arcs, 'arc')}"
               + (f", {impossible} R arcs that cannot exist drawn as chords" if impossible
                  else "")
               + (f"; not drawn: {' '.join(bp.not_drawn)}" if bp.not_drawn else ""))
    unreadable = sum(f.severity == "error" and f.rule in READING_RULES for f in bp.findings)
    if not bp.moves and unreadable:
        # an empty picture of a file that is no program is no answer: say so, exit 1
        click.echo(f"{shown_output(file)}: nothing to draw: "
                   f"{plural(unreadable, 'block')} cannot be read "
                   f"(tapegate check {shown_output(file)} shows why)", err=True)
        sys.exit(1)


# ---------------------------------------------------------------------------------------------
# tape


@main.group(short_help="Encode, decode and detect punched-tape images (ISO, EIA).")
def tape() -> None:
    """Encode and decode punched-tape images (ISO even parity, EIA RS-244)."""


@tape.command("encode")
@click.argument("infile", type=click.Path(dir_okay=False))
@click.option("-o", "--output", required=True, type=click.Path(dir_okay=False))
@click.option("--code", type=click.Choice(["iso", "eia"]), default="iso", show_default=True)
@click.option("--leader", type=click.IntRange(0), default=0, help="Blank characters before.")
@click.option("--trailer", type=click.IntRange(0), default=0, help="Blank characters after.")
@user_errors
def tape_encode(infile: str, output: str, code: str, leader: int, trailer: int) -> None:
    """Text program -> tape image (in flat memory, whatever its size)."""
    from formats.parser import decode_chunks, read_chunks
    from formats.tape import encode_stream

    chunks = decode_chunks(read_chunks(readable(infile)))
    data = encode_stream(chunks, code, leader=leader, trailer=trailer,  # type: ignore[arg-type]
                         file=shown(infile))
    size = write_stream(output, data)
    click.echo(f"{shown_output(output)}: {size} bytes, {code.upper()} code",
               err=output == "-")


@tape.command("decode")
@click.argument("infile", type=click.Path(dir_okay=False))
@click.option("-o", "--output", required=True, type=click.Path(dir_okay=False))
@click.option("--code", type=click.Choice(["iso", "eia"]), default=None,
              help="Force the code instead of detecting it.")
@user_errors
def tape_decode(infile: str, output: str, code: str | None) -> None:
    """Tape image -> text; every parity error and illegal code located, the data kept (in flat
    memory: the errors are shown as they are found)."""
    from formats.parser import read_chunks
    from formats.tape import decode_stream

    decoder, texts = decode_stream(read_chunks(readable(infile)), code)  # type: ignore[arg-type]
    counts = {"characters": 0, "errors": 0}

    def encoded() -> Iterator[bytes]:
        for text in texts:
            counts["characters"] += len(text)
            for issue in decoder.issues:
                click.echo(f"{shown(infile)}:{issue.line}:{issue.column}: {issue.message()} "
                           f"at byte {issue.offset}", err=True)
            counts["errors"] += len(decoder.issues)
            decoder.issues.clear()
            yield text.encode("utf-8", errors="surrogateescape")

    write_stream(output, encoded())
    click.echo(f"{shown_output(output)}: {decoder.code.upper()} code, "
               f"{counts['characters']} characters, "
               f"{decoder.fill} fill characters removed, {counts['errors']} errors",
               err=output == "-")
    if counts["errors"]:
        sys.exit(1)


@tape.command("detect")
@click.argument("infile", type=click.Path(dir_okay=False))
@user_errors
def tape_detect(infile: str) -> None:
    """Say whether a file is plain text, an ISO tape image or an EIA tape image (exit 0), or
    none of them: binary (exit 1)."""
    from formats.tape import identify

    with open(readable(infile), "rb") as f:
        sample = f.read(65536)
    content, foreign = identify(sample)
    click.echo(content)
    if content == "binary":
        click.echo(f"{shown(infile)}: {foreign} of the first {len(sample)} bytes are no "
                   "character of text, an ISO tape or an EIA tape", err=True)
        sys.exit(1)


# ---------------------------------------------------------------------------------------------
# classify and profiles


@main.command(short_help="Explain an Annex B or Annex C classification string.")
@click.argument("classification", nargs=-1, required=True)
@user_errors
def classify(classification: tuple[str, ...]) -> None:
    """Explain an Annex B ('PM 322') or Annex C ('%:/DS N03 ... M02*') classification."""
    from formats.classification import DetailedClassification, parse_classification

    parsed = parse_classification(" ".join(classification))
    if isinstance(parsed, DetailedClassification):
        click.echo(f"detailed format classification (ISO 6983-1 Annex C)\n  {parsed}\n")
    else:
        click.echo(f"general format classification (ISO 6983-1 Annex B)\n  {parsed}\n")
    rows = parsed.explain()
    click.echo(table(("item", "value", "meaning"), rows))


def table(header: tuple[str, ...], rows: Sequence[tuple[str, ...]]) -> str:
    widths = [max(len(str(r[i])) for r in [header, *rows]) for i in range(len(header))]
    lines = ["  ".join(str(c).ljust(w) for c, w in zip(header, widths, strict=True)).rstrip()]
    lines.append("  ".join("-" * w for w in widths))
    for row in rows:
        lines.append("  ".join(str(c).ljust(w) for c, w in zip(row, widths, strict=True)).rstrip())
    return "\n".join(lines)


@main.group(invoke_without_command=True)
@click.pass_context
def profiles(ctx: click.Context) -> None:
    """List the built-in machine profiles."""
    if ctx.invoked_subcommand is None:
        rows = []
        for name in builtin_names():
            p = load_profile(name)
            rows.append((name, str(p.general), p.table.name, p.serial.code.upper(),
                         p.description))
        click.echo(table(("name", "class", "codes", "tape", "description"), rows))


@profiles.command("show")
@click.argument("name")
@user_errors
def profiles_show(name: str) -> None:
    """Print a profile's TOML (a built-in name or a file), after checking it loads."""
    prof = load_profile(name)
    text = builtin_text(name) if prof.source == "built-in" else Path(name).read_text()
    click.echo(text, nl=False)
    if not text.strip():
        click.echo(f"{name}: an empty profile: every setting at its default", err=True)




# ---------------------------------------------------------------------------------------------
# diff


@main.command(short_help="Compare two programs as NC: blocks, words and values, not text.")
@click.argument("file_a", metavar="A", type=click.Path(dir_okay=False))
@click.argument("file_b", metavar="B", type=click.Path(dir_okay=False))
@click.option("--profile", "-p", "profile", default=None,
              help="B's machine profile, and A's without --from (default: the neutral "
                   "profile, with the units codes and decimal style detected in each program).")
@click.option("--from", "from_profile", default=None, help="A's machine profile.")
@click.option("--tolerance", default="0", show_default=True, metavar="STEPS",
              help="Largest difference accepted, in resolution steps of B's word format "
                   "(0.5: what rounding to B's resolution may leave).")
@click.option("--ignore-comments", is_flag=True, help="Comments and comment-only blocks too.")
@click.option("--motion", is_flag=True,
              help="Also compare the modal state and end point after every block.")
@click.option("--pair", type=click.Choice(["auto", "number", "position"]), default="auto",
              show_default=True, help="Pair blocks by sequence number or by position.")
@click.option("--format", "fmt", type=click.Choice(["text", "json"]), default="text",
              show_default=True)
def diff(file_a: str, file_b: str, profile: str | None, from_profile: str | None,
         tolerance: str, ignore_comments: bool, motion: bool, pair: str, fmt: str) -> None:
    """Compare program A with program B as NC: the same blocks, words and values, whatever
    the spacing, zeros, decimal style, units (and, with --ignore-comments, comments).

    Exit 0 the same, 1 different, 2 an error (a file that cannot be read, with its line and
    column)."""
    import json
    from decimal import Decimal, InvalidOperation

    from formats.diff import Differ, DiffOptions, diff_files

    try:
        steps = Decimal(tolerance)
        if not steps.is_finite() or steps < 0:
            raise InvalidOperation
    except InvalidOperation:
        raise UsageProblem(f"--tolerance {tolerance}: give a number of steps, 0 or more"
                           ) from None
    if file_a == file_b == "-":
        raise UsageProblem("- (standard input) can be one of the two programs, not both")
    name_a, name_b = shown(file_a), shown(file_b)
    try:
        path_a, path_b = readable(file_a), readable(file_b)
        prof_a = _diff_profile(from_profile or profile, path_a, name_a)
        prof_b = _diff_profile(profile, path_b, name_b)
        options = DiffOptions(tolerance=steps, ignore_comments=ignore_comments, motion=motion,
                              pair=pair)  # type: ignore[arg-type]
        differ = Differ(options, prof_b)
        found = diff_files(path_a, path_b, prof_a, prof_b, options, name_a=name_a,
                           name_b=name_b, differ=differ)
        out = sys.stdout
        if fmt == "json":
            head = {"a": {"file": name_a, "profile": prof_a.name},
                    "b": {"file": name_b, "profile": prof_b.name},
                    "options": {"tolerance": tolerance, "motion": motion,
                                "ignore_comments": ignore_comments, "pair": pair}}
            out.write(json.dumps(head)[:-1] + ', "differences": [')
            for i, item in enumerate(found):
                out.write((",\n  " if i else "\n  ") + json.dumps(item.as_json()))
            out.write('\n], "summary": ' + json.dumps(differ.summary.as_json()) + "}\n")
        else:
            for item in found:
                out.write(_diff_text(item, name_a, name_b))
            out.write(_diff_summary(differ, name_a, name_b) + "\n")
        out.flush()
    except BrokenPipeError:
        _silence_stdout()
        sys.exit(0)
    except ProfileError as exc:
        click.echo(f"tapegate: {exc}", err=True)
        sys.exit(2)
    except TapegateError as exc:
        click.echo(str(exc), err=True)
        sys.exit(2)
    except OSError as exc:
        click.echo(f"tapegate: cannot read {exc.filename}: {exc.strerror or exc}", err=True)
        sys.exit(2)
    sys.exit(0 if differ.summary.same else 1)


def _diff_profile(name: str | None, path: str, shown_name: str) -> Profile:
    """A named profile, or the neutral one adjusted to what the program shows (said on
    stderr, naming the file: two programs may be read two ways)."""
    if name is not None:
        return load_profile(name)
    from formats.convert import detect_source

    head = next(iter(Source(path).chunks()), "")
    prof, detected = detect_source(head[:1 << 20])
    notes = ["the neutral profile"] + [note.removeprefix("source: ") for note in detected]
    click.echo(f"tapegate: {shown_name}: " + "; ".join(notes), err=True)
    return prof


def _diff_text(item: Any, name_a: str, name_b: str) -> str:
    if item.kind == "removed":
        return f"{name_a}:{item.a.line}: only in {name_a}: {item.a.shown}\n"
    if item.kind == "added":
        return f"{name_b}:{item.b.line}: only in {name_b}: {item.b.shown}\n"
    lines = [f"{name_a}:{item.a.line}: changed: {item.a.shown}",
             f"{name_b}:{item.b.line}:     is: {item.b.shown}"]
    lines += [f"    {detail}" for detail in item.details()]
    return "\n".join(lines) + "\n"


def _diff_summary(differ: Any, name_a: str, name_b: str) -> str:
    s = differ.summary
    paired = f"{plural(s.paired, 'block')} paired by {s.pairing}"
    if s.same:
        return f"{name_a} and {name_b} are the same program ({paired})"
    parts = [f"{plural(s.changed, 'block')} changed" if s.changed else "",
             f"{s.removed} only in {name_a}" if s.removed else "",
             f"{s.added} only in {name_b}" if s.added else ""]
    text = f"{name_a} and {name_b} differ: {', '.join(p for p in parts if p)} ({paired})"
    if s.largest:
        from formats.diff import steps_text

        key, size = max(s.largest.items(), key=lambda kv: kv[1])
        text += f"; largest difference: {key} {steps_text(size).lstrip('+')}"
        from fractions import Fraction

        if (max(s.largest.values()) <= Fraction(1, 2) and not differ.options.tolerance
                and not (s.added or s.removed or s.other)):
            text += " (within half a step: --tolerance 0.5 accepts a rounding)"
    return text
