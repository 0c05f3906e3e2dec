"""`check -j` and `convert -j`: files in threads (the core works with the GIL released),
reports in input order, byte for byte what one thread writes (tapegate.workers)."""

from __future__ import annotations

import contextlib
import json
import os
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

import pytest
from click.testing import CliRunner

from tapegate.cli import main
from tapegate.workers import (
    BATCH,
    EARLY,
    PIECES,
    RUN,
    WAITING,
    WINDOW,
    default_jobs,
    first,
    input_files,
    ordered_map,
    send,
)

from .conftest import CORPUS, corpus_files

ROOT = Path(__file__).resolve().parent.parent

PROGRAM = "%\nN1 G21 G90 G94\nN2 G01 X25.4 Y12.7 F254.\nN3 G02 X30. Y20. I5. J0\nM30\n%\n"
# findings of several rules and severities: a word out of order, an unknown code, no M30
ODD = "%\nN1 G21 G90\nN2 X10. G01 F100.\nN3 G77 X20.\nN4 S99999 M03\n%\n"


def _wait_for(path: Path, seconds: float = 20.0) -> None:
    deadline = time.monotonic() + seconds
    while not path.exists():
        if time.monotonic() > deadline:
            raise TimeoutError(f"{path} did not appear")
        time.sleep(0.01)


def _slow_first(item: tuple[int, str]) -> tuple[int, list[str]]:
    """Item 0 finishes last: it waits until the last item 2 threads may be given beside it
    has run, then says which items started."""
    number, folder = item
    (Path(folder) / f"started-{number}").touch()
    if number == 0:
        _wait_for(Path(folder) / f"started-{2 * WINDOW - 1}")
        _wait_for(Path(folder) / f"done-{2 * WINDOW - 1}")
    else:
        (Path(folder) / f"done-{number}").touch()
    return number, sorted(p.name for p in Path(folder).glob("started-*"))


def test_results_come_in_input_order_and_at_most_a_window_per_worker_wait(tmp_path):
    items = [(n, str(tmp_path)) for n in range(3 * WINDOW)]
    results = list(ordered_map(_slow_first, items, 2))
    assert [n for n, _ in results] == list(range(3 * WINDOW))
    # when item 0 (the first) finished, the items after it up to 2 * WINDOW had run and no
    # more had been given out: 2 threads hold 2 * WINDOW items at most, however long the
    # first one takes
    assert results[0][1] == sorted(f"started-{n}" for n in range(2 * WINDOW))


def _fails_on_two(item: int) -> int:
    if item == 2:
        raise ValueError("item 2 is bad")
    return item * 10


def test_an_exception_in_a_worker_is_raised_at_its_turn():
    got = []
    with pytest.raises(ValueError, match="item 2 is bad"):
        for result in ordered_map(_fails_on_two, list(range(6)), 2):
            got.append(result)
    assert got == [0, 10]


def test_one_job_runs_here_in_order():
    assert list(ordered_map(_fails_on_two, [0, 1], 1)) == [0, 10]
    assert default_jobs() >= 1


def test_a_folder_is_every_file_in_it_sorted_hidden_ones_left_out(tmp_path):
    (tmp_path / "b").mkdir()
    (tmp_path / "b" / "z.nc").write_text(PROGRAM)
    (tmp_path / "a.nc").write_text(PROGRAM)
    (tmp_path / ".git").mkdir()
    (tmp_path / ".git" / "x.nc").write_text(PROGRAM)
    (tmp_path / ".hidden.nc").write_text(PROGRAM)
    assert input_files([str(tmp_path), "-", "missing.nc"]) == [
        str(tmp_path / "a.nc"), str(tmp_path / "b" / "z.nc"), "-", "missing.nc"]


def test_a_folder_lists_as_pathlib_would_without_importing_it(tmp_path, monkeypatch):
    """The order of the parts (``a/b/x`` before ``a/b.nc`` before ``a-c/``), links to files
    in, a folder linked to not entered, a link that leads nowhere in (reading it reports it:
    left out, a file would go unread in silence), and the names as pathlib writes them
    (``./cam/`` is ``cam``)."""
    import pathlib

    cam = tmp_path / "cam"
    for folder in ("a/b", "a-c", ".git", "Z"):
        (cam / folder).mkdir(parents=True)
    for name in ("a/b/x.nc", "a-c/y.nc", "a.nc", "a b.nc", ".h.nc", ".git/q", "Z/1", "é.nc",
                 "a/b.nc"):
        (cam / name).write_text(PROGRAM)
    (cam / "link.nc").symlink_to("a.nc")
    (cam / "linked").symlink_to("a")
    (cam / "broken.nc").symlink_to("nowhere")

    def by_pathlib(name: str) -> list[str]:
        path = pathlib.Path(name)
        return [str(found) for found in sorted(path.rglob("*"))
                if (found.is_file() or (found.is_symlink() and not found.exists()))
                and not any(p.startswith(".") for p in found.relative_to(path).parts)]

    monkeypatch.chdir(tmp_path)
    for name in ("cam", "./cam/", str(cam), "cam//a", "cam/../cam"):
        assert input_files([name]) == by_pathlib(name), name
    monkeypatch.chdir(cam)
    assert input_files(["."]) == by_pathlib(".") == [
        "Z/1", "a/b/x.nc", "a/b.nc", "a b.nc", "a-c/y.nc", "a.nc", "broken.nc", "link.nc",
        "é.nc"]


def test_a_link_that_leads_nowhere_in_a_folder_is_reported_not_read(tmp_path):
    """A folder's symbolic link to a file that is gone is one of its files that could not be
    read (exit 2, its message), as the same link named alone is, never left out in silence."""
    cam = tmp_path / "cam"
    cam.mkdir()
    (cam / "a.nc").write_text(PROGRAM)
    (cam / "b.nc").symlink_to("gone.nc")
    for jobs in ("1", "2"):
        result = _run("check", str(cam), "-p", "fanuc-mill", "-j", jobs)
        assert result.exit_code == 2, (jobs, result.output)
        assert f"cannot read {cam / 'b.nc'}: No such file or directory" in result.stderr


def _folder(tmp_path: Path) -> Path:
    cam = tmp_path / "cam"
    (cam / "op2").mkdir(parents=True)
    for n in range(7):
        text = ODD if n % 2 else PROGRAM
        (cam / ("op2" if n > 3 else "") / f"p{n}.nc").write_text(text.replace("X20.", f"X2{n}."))
    (cam / "p9.nc").write_bytes(bytes(range(256)) * 4)  # a binary file: TG101 findings
    # the last line without its end of block (read by the parser, not the core's lines)
    (cam / "p8.nc").write_text(ODD.rstrip("%\n"))
    return cam


def _run(*args: str):
    return CliRunner().invoke(main, list(args))


@pytest.mark.parametrize("fmt", ["text", "json", "jsonl", "sarif"])
def test_check_of_a_folder_in_two_workers_equals_one_byte_for_byte(tmp_path, fmt):
    cam = _folder(tmp_path)
    missing = str(tmp_path / "nope.nc")  # not readable: its error, in its place
    loop = tmp_path / "loop.nc"  # exists, and cannot be opened
    loop.symlink_to(loop)
    args = ["check", str(cam), missing, str(loop), str(cam / "p1.nc"), "-p", "fanuc-mill",
            "--format", fmt, "--stats"]
    one = _run(*args, "-j", "1")
    two = _run(*args, "-j", "2")
    three = _run(*args, "-j", "3")
    assert one.exception is None or isinstance(one.exception, SystemExit), one.exception
    assert one.exit_code == 2  # a file could not be read
    assert (two.exit_code, two.stdout, two.stderr) == (one.exit_code, one.stdout, one.stderr)
    assert (three.exit_code, three.stdout, three.stderr) == (one.exit_code, one.stdout,
                                                             one.stderr)
    assert f"cannot read {missing}: No such file or directory" in one.stderr
    assert f"cannot read {loop}: Too many levels of symbolic links" in one.stderr
    assert one.stderr.index(missing) < one.stderr.index(str(loop))  # in the input's order
    if fmt == "text":
        assert "10 files checked (2 not read)" in one.stderr
    assert "p1.nc" in one.stdout and "TG101" in one.stdout
    if fmt == "jsonl":  # the findings come file by file, in the order of the input
        files = [json.loads(line)["file"] for line in one.stdout.splitlines()
                 if '"rule"' in line]
        order = [str(p) for p in sorted(cam.rglob("*.nc"))] + [str(cam / "p1.nc")]
        seen = [f for i, f in enumerate(files) if i == 0 or files[i - 1] != f]
        assert seen == [f for f in order if f in files]
    if fmt == "json":
        document = json.loads(one.stdout)
        assert len(document["stats"]) == 9  # the files read (p1.nc, given twice, is one)
        assert document["findings"][0]["file"] == str(cam / "op2" / "p4.nc")  # sorted first
    if fmt == "sarif":
        results = json.loads(one.stdout)["runs"][0]["results"]
        rules = json.loads(one.stdout)["runs"][0]["tool"]["driver"]["rules"]
        first_seen = list(dict.fromkeys(r["ruleId"] for r in results))
        assert [r["id"] for r in rules] == first_seen
        assert all(rules[r["ruleIndex"]]["id"] == r["ruleId"] for r in results)


def test_check_of_a_file_with_no_findings_in_workers(tmp_path):
    for n in range(3):
        (tmp_path / f"p{n}.nc").write_text(PROGRAM)
    one = _run("check", str(tmp_path), "-p", "iso-mill", "--format", "json", "-j", "1",
               "--select", "TG601")
    two = _run("check", str(tmp_path), "-p", "iso-mill", "--format", "json", "-j", "2",
               "--select", "TG601")
    assert one.exit_code == two.exit_code == 0
    assert one.stdout == two.stdout == '{\n  "findings": []\n}\n'


def test_an_empty_folder_is_a_usage_error(tmp_path):
    (tmp_path / "empty").mkdir()
    result = _run("check", str(tmp_path / "empty"), "-p", "iso-mill")
    assert result.exit_code == 2
    assert f"no file to check in {tmp_path / 'empty'}" in result.output


def test_convert_in_two_workers_equals_one(tmp_path):
    cam = tmp_path / "cam"
    cam.mkdir()
    for n in range(6):
        (cam / f"p{n}.nc").write_text(PROGRAM.replace("X25.4", f"X25.{n}"))
    (cam / "big.nc").write_text("N1 X1.\nN2 X12345678.\n")  # fails in its worker
    outputs = {}
    for jobs in ("1", "2"):
        out = tmp_path / f"out{jobs}"
        result = _run("convert", str(cam), "--out-dir", str(out), "--to", "iso-mill",
                      "--units", "inch", "-j", jobs)
        assert result.exit_code == 1
        assert "big.nc:2:4: X12345678. is 486050.315 in the target format" in result.stderr
        outputs[jobs] = (result.stdout.replace(str(out), "OUT"), result.stderr,
                         {p.name: p.read_bytes() for p in sorted(out.iterdir())})
    assert outputs["1"] == outputs["2"]
    rows = [line.split()[0] for line in outputs["1"][0].splitlines()[2:-1]]
    assert rows == [str(cam / "big.nc")] + [str(cam / f"p{n}.nc") for n in range(6)]



@pytest.mark.skipif(not (CORPUS / "shops").is_dir(), reason="shared/corpus/shops is not present")
def test_convert_of_the_shops_folder_in_two_workers_replacing_its_outputs_equals_one(tmp_path):
    """Real programs (their source read from each), converted into a folder that already
    holds their outputs (--force: each commit a rename over the old file, as a batch run again
    does), with one worker and two: the same files byte for byte, the same report, no
    temporary file left; and each output is what the file converted alone gives."""
    from formats.convert import ConvertOptions, convert_file
    from formats.profile import load_profile

    shops = CORPUS / "shops"
    args = ["convert", str(shops), "--force", "--to", "iso-mill", "--units", "inch"]
    outputs = {}
    for jobs in ("1", "2"):
        out = tmp_path / f"out{jobs}"
        for _ in range(2):  # the second run replaces every output the first one made
            result = _run(*args, "--out-dir", str(out), "-j", jobs)
        outputs[jobs] = (result.exit_code, result.stdout.replace(str(out), "OUT"),
                         result.stderr.replace(str(out), "OUT"),
                         {p.name: p.read_bytes() for p in sorted(out.iterdir())})
        assert not [p.name for p in out.iterdir() if p.name.endswith(".part")]
    assert outputs["1"] == outputs["2"]
    written = outputs["2"][3]
    assert len(written) >= 20  # (the others are refused, each with its reason, in both)
    options = ConvertOptions(target=load_profile("iso-mill"), units="inch")
    for name in sorted(written):
        alone = tmp_path / "alone" / name
        convert_file(str(shops / name), str(alone), options)
        assert alone.read_bytes() == written[name], name


def test_temporary_files_made_and_committed_from_many_threads_at_once(tmp_path):
    """The core's temporary files (``pending_file``) made by several threads while the
    commit threads name others in the same folder: every output named with its own bytes,
    each temporary name drawn once, nothing left behind (the list of temporary files is not
    held across the folder's ``open``, nor a commit's state lock across a thread's wake-up:
    crates/python/src/commits.rs)."""
    import threading

    from formats import _core

    out = tmp_path / "out"
    out.mkdir()
    for n in range(0, 240, 3):  # a third replaces an output already there
        (out / f"p{n}.nc").write_text("old\n")
    commits = _core.Commits(2)
    made: list[str] = []
    tickets: list[int] = []
    lock = threading.Lock()

    def worker(first: int) -> None:
        for n in range(first, 240, 4):
            fd, tmp = _core.pending_file(str(out), f"p{n}.nc")
            os.write(fd, f"program {n}\n".encode() * 50)
            ticket = commits.submit(fd, tmp, str(out / f"p{n}.nc"), True)
            with lock:
                made.append(tmp)
                tickets.append(ticket)

    threads = [threading.Thread(target=worker, args=(k,)) for k in range(4)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    for ticket in tickets:
        commits.wait(ticket)
    commits.close()
    assert len(set(made)) == 240
    assert sorted(p.name for p in out.iterdir()) == sorted(f"p{n}.nc" for n in range(240))
    for n in range(240):
        assert (out / f"p{n}.nc").read_bytes() == f"program {n}\n".encode() * 50
    assert _core.sweep_pending() == 0  # every temporary file named, none listed

@pytest.mark.skipif(not corpus_files(), reason="shared/corpus is not present")
def test_check_of_the_corpus_in_two_workers_equals_one():
    args = ["check", str(CORPUS), "-p", "fanuc-mill", "--format", "jsonl", "--stats"]
    one = _run(*args, "-j", "1")
    two = _run(*args, "-j", "2")
    assert (two.exit_code, two.stdout, two.stderr) == (one.exit_code, one.stdout, one.stderr)
    assert one.stdout.count('"stats"') == len(input_files([str(CORPUS)]))


SHOPS = CORPUS / "shops"


@pytest.mark.skipif(not SHOPS.is_dir(), reason="shared/corpus/shops is not present")
@pytest.mark.parametrize("fmt", ["text", "json", "jsonl", "sarif"])
def test_check_of_the_shops_folder_in_two_threads_equals_one_byte_for_byte(tmp_path, fmt):
    """123 real programs of every family (findings by the thousand, tens of MB of SARIF),
    the report on a real stdout."""
    args = [sys.executable, "-m", "tapegate", "check", str(SHOPS), "-p", "fanuc-mill",
            "--format", fmt, "--stats"]
    runs = {}
    for jobs in ("1", "2"):
        with open(tmp_path / f"report{jobs}", "wb") as out:
            done = subprocess.run([*args, "-j", jobs], stdout=out, stderr=subprocess.PIPE,
                                  cwd=ROOT, timeout=600, check=False)
        runs[jobs] = (done.returncode, done.stderr, (tmp_path / f"report{jobs}").read_bytes())
    assert runs["1"][0] == 1  # errors found, every file read
    assert runs["2"] == runs["1"]
    assert len(runs["1"][2]) > 100_000


CLEAN = "%\nN1 G21 G90 G94\nN2 G01 X25.4 Y12.7 F254.\nM30\n%\n"  # notes only
WARNS = CLEAN.replace("M30", "N3 G77 X1.\nM30")  # TG307, a warning


@pytest.mark.parametrize(("text", "fail_on", "code"), [
    (CLEAN, "warning", 0), (WARNS, "error", 0), (WARNS, "warning", 1), (PROGRAM, "error", 1)])
def test_the_exit_code_of_two_threads_is_one_threads(tmp_path, text, fail_on, code):
    """The worst finding of any file decides, whichever thread checked it."""
    for n in range(5):
        (tmp_path / f"p{n}.nc").write_text(CLEAN if n != 3 else text)
    results = [_run("check", str(tmp_path), "-p", "fanuc-mill", "--fail-on", fail_on, "-j", j)
               for j in ("1", "2")]
    assert [r.exit_code for r in results] == [code, code]
    assert results[0].stdout == results[1].stdout
    assert results[0].stderr == results[1].stderr


# -- pieces sent by the threads ----------------------------------------------------------------


def _sends(item: int) -> int:
    for n in range(item):
        send((item, n))
    return item


def _sent_in_order(items: int | list[int]) -> list[object]:
    """What ``receive`` and the results give for :func:`_sends` over ``items`` (a count:
    0, 1, ...): each item's pieces, then its result, in the items' order."""
    expected: list[object] = []
    for item in (range(items) if isinstance(items, int) else items):
        expected.extend((item, n) for n in range(item))
        expected.append(item)
    return expected


def test_pieces_reach_receive_in_the_items_order_before_their_result():
    got: list[object] = []
    for result in ordered_map(_sends, [3, 0, 5, 1, 2, 4], 2, receive=got.append):
        got.append(result)
    assert got == _sent_in_order([3, 0, 5, 1, 2, 4])
    one: list[object] = []  # one job: at once, in this thread
    for result in ordered_map(_sends, [2, 1], 1, receive=one.append):
        one.append(result)
    assert one == [(2, 0), (2, 1), 2, (1, 0), 1]


def test_the_main_thread_is_woken_once_for_a_run_of_items_done():
    """An item done wakes the main thread only once the items done in a row from the one
    whose turn it is are RUN, or every item is given out, or (the due one done) the waiting
    items hold half their budget: not once an item, which took a core from a working thread
    each time."""
    import tapegate.workers as workers

    state = workers._Map(lambda item: item, list(range(20)), 8, 8)
    state.given = 10

    def done(*indexes: int) -> None:
        for index in indexes:
            slot = state.slots[index] = workers._Slot(index)
            slot.done = True

    assert not state._ready()  # nothing done
    done(1, 2, 3)
    assert not state._ready()  # the item whose turn it is (0) still running
    done(0)
    assert RUN == 4 and state._ready()  # 0, 1, 2, 3
    del state.slots[3]
    assert not state._ready()  # 0, 1, 2: the threads go on without waking it
    state.held = 4  # half the budget held by the items not yet due
    assert state._ready()
    state.held = 0
    state.given = 20  # every item given: the batch's end, each item taken as it is done
    assert state._ready()
    state.slots.clear()
    assert not state._ready()


@pytest.mark.parametrize("window", [1, 2])
def test_threads_waiting_for_the_window_wake_the_main_thread(monkeypatch, window):
    """A window of fewer items a thread than a RUN: the items done are not enough to wake the
    main thread, so a thread that must wait for the window to move wakes it before it waits;
    every result comes, in order."""
    import threading

    import tapegate.workers as workers

    monkeypatch.setattr(workers, "WINDOW", window)
    assert 2 * window < 2 * RUN
    results: list[object] = []

    def consume() -> None:
        results.extend(ordered_map(_sends, list(range(40)), 2, receive=results.append))

    thread = threading.Thread(target=consume, daemon=True)
    thread.start()
    thread.join(timeout=60)
    assert not thread.is_alive(), "the map waited for ever"
    assert results == _sent_in_order(40)


def test_a_thread_whose_item_is_not_due_waits_with_at_most_pieces_of_it(tmp_path):
    """Memory stays flat: item 1 sends many pieces (not text) while item 0 is not done; its
    thread waits once it holds WAITING of them a thread (2 threads), and goes on when they are
    taken."""
    import threading

    flag = tmp_path / "first-may-end"
    sent = [0]
    at_release: list[int] = []

    def slow_first(item: int) -> int:
        if item == 0:
            _wait_for(flag)
            return 0
        for n in range(3 * PIECES):
            send(n)
            sent[0] += 1
        return 1

    def release() -> None:
        # first the condition: item 1's thread has sent 2 * WAITING pieces (or more, which
        # the assertion below catches); then a window in which a thread that did not wait
        # would send its next piece, before item 0 may end
        deadline = time.monotonic() + 20.0
        while sent[0] < 2 * WAITING and time.monotonic() < deadline:
            time.sleep(0.005)
        window = time.monotonic() + 0.2
        while sent[0] == 2 * WAITING and time.monotonic() < window:
            time.sleep(0.005)
        at_release.append(sent[0])
        flag.touch()

    threading.Thread(target=release).start()
    pieces: list[int] = []
    assert list(ordered_map(slow_first, [0, 1], 2, receive=pieces.append)) == [0, 1]
    assert 3 * PIECES > 2 * WAITING  # (more than the two threads may hold)
    assert at_release == [2 * WAITING]
    assert pieces == list(range(3 * PIECES))


def test_the_due_items_pieces_reach_receive_in_batches_while_it_runs():
    """The item whose turn it is streams: once it has sent BATCH pieces they are taken (all of
    them, the main thread woken once) while it still runs, and every piece comes in order."""
    import threading

    got: list[int] = []
    taken = threading.Event()

    def receive(piece: int) -> None:
        got.append(piece)
        if len(got) == BATCH:
            taken.set()

    def long_first(item: int) -> int:
        if item == 0:
            for n in range(BATCH):
                send(n)
            if not taken.wait(timeout=30):  # not taken until the item's end: fails below
                raise AssertionError("the due item's pieces were not taken while it ran")
            for n in range(BATCH, 3 * PIECES):
                send(n)
        return item

    assert list(ordered_map(long_first, [0, 1], 2, receive=receive)) == [0, 1]
    assert got == list(range(3 * PIECES))


def _raises_after_sending(item: int) -> int:
    send(f"piece of {item}")
    if item == 1:
        raise OSError("item 1 is bad")
    return item


def test_an_exception_comes_after_the_pieces_its_item_sent_and_stops_the_rest():
    got: list[object] = []
    with pytest.raises(OSError, match="item 1 is bad"):
        for result in ordered_map(_raises_after_sending, list(range(20)), 2,
                                  receive=got.append):
            got.append(result)
    assert got == ["piece of 0", 0, "piece of 1"]


# -- the report on a real stdout ----------------------------------------------------------------


@pytest.mark.parametrize("fmt", ["json", "text", "jsonl"])
def test_a_check_written_to_a_file_and_a_pipe_is_the_same_with_two_workers(tmp_path, fmt):
    """stdout a real file and a pipe: the report equals -j 1's byte for byte, and the first
    file's findings open the JSON document."""
    cam = _folder(tmp_path)
    args = [sys.executable, "-m", "tapegate", "check", str(cam), "-p", "fanuc-mill",
            "--format", fmt]
    reports = {}
    for jobs in ("1", "2"):
        with open(tmp_path / f"report{jobs}", "wb") as out:
            done = subprocess.run([*args, "-j", jobs], stdout=out, stderr=subprocess.PIPE,
                                  cwd=ROOT, timeout=120, check=False)
        assert done.returncode == 1, done.stderr  # findings, errors among them
        reports[jobs] = (tmp_path / f"report{jobs}").read_bytes()
    piped = subprocess.run([*args, "-j", "2"], capture_output=True, cwd=ROOT, timeout=120,
                           check=False)
    assert reports["2"] == reports["1"] == piped.stdout
    if fmt == "json":
        assert reports["1"].startswith(b'{\n  "findings": [\n    {\n')
        assert len(json.loads(reports["1"])["findings"]) > 10


def test_a_report_appended_to_a_file_keeps_what_the_file_held(tmp_path):
    """A file opened to append (>>): the report comes after what it held."""
    cam = _folder(tmp_path)
    report = tmp_path / "report.json"
    report.write_bytes(b"before\n")
    with open(report, "ab") as out:
        subprocess.run([sys.executable, "-m", "tapegate", "check", str(cam), "-p", "fanuc-mill",
                        "--format", "json", "-j", "2"], stdout=out, stderr=subprocess.PIPE,
                       cwd=ROOT, timeout=120, check=False)
    one = _run("check", str(cam), "-p", "fanuc-mill", "--format", "json", "-j", "1")
    assert report.read_bytes() == b"before\n" + one.stdout_bytes


# -- convert: the folders fsync'd once for the batch ----------------------------------------------


def test_a_batch_syncs_each_output_folder_once(tmp_path, monkeypatch):
    import formats.files

    cam = tmp_path / "cam"
    (cam / "sub").mkdir(parents=True)
    for n in range(4):
        (cam / ("sub" if n > 1 else "") / f"p{n}.nc").write_text(PROGRAM)
    folders: list[str] = []
    monkeypatch.setattr(formats.files, "_sync_folder", lambda f: folders.append(str(f)))
    monkeypatch.setattr(formats.files, "sync_folder", lambda f: folders.append(str(f)))
    out = tmp_path / "out"
    result = _run("convert", str(cam), "--out-dir", str(out), "--to", "iso-mill", "--units",
                  "inch", "-j", "1")
    assert result.exit_code == 0, result.output
    assert sorted(folders) == [str(out), str(out / "sub")]  # once each, at the end
    assert sorted(p.name for p in out.rglob("*.nc")) == [f"p{n}.nc" for n in range(4)]


def _traced(tmp_path: Path, *args: str) -> tuple[int, list[tuple[int, str]]]:
    """(the process's ID, its threads' calls of fsync, rename, link and unlink and its opens,
    as ``strace -f -y`` tells them: (thread, call)) of ``python -m tapegate ARGS``; the test
    is skipped where strace is missing or may not trace."""
    import shutil

    if shutil.which("strace") is None:
        pytest.skip("strace is not installed")
    log = tmp_path / "strace.log"
    done = subprocess.run(["strace", "-f", "-y", "-qq", "-o", str(log), "-e",
                           "trace=fsync,rename,renameat,renameat2,link,linkat,unlink,unlinkat,"
                           "openat", sys.executable, "-m", "tapegate", *args],
                          capture_output=True, text=True, cwd=ROOT, timeout=300, check=False,
                          env={**os.environ, "PYTHONPATH": str(ROOT)})
    if not log.exists() or "ptrace" in done.stderr:
        pytest.skip(f"strace may not trace here: {done.stderr[-300:]}")
    assert done.returncode == 0, done.stderr
    calls = []
    for line in log.read_text().splitlines():
        thread, _, call = line.partition(" ")
        calls.append((int(thread), call.strip()))
    return min(t for t, _ in calls), calls


@pytest.mark.parametrize("jobs", ["1", "2"])
def test_every_output_is_synced_before_its_name_and_not_by_a_converting_thread(tmp_path, jobs):
    """The commits of a batch (tapegate.converting.Commits, the core's Commits): each output's
    temporary file is fsync'd before it is given its name (a link, or with --force a rename),
    its temporary name then removed, by a thread of the commits: not the main thread, which
    converts (with -j 1, the next file while the disk writes the last output) -- read from
    the system calls themselves (strace)."""
    import re

    cam = tmp_path / "cam"
    cam.mkdir()
    for n in range(4):
        (cam / f"p{n}.nc").write_text(PROGRAM.replace("X25.4", f"X25.{n}"))
    out = tmp_path / "out"
    out.mkdir()
    force = ["--force"] if jobs == "2" else []  # (-j 2: a rename, -j 1: a link)
    if force:
        (out / "p3.nc").write_text("old\n")  # replaced
    main_thread, calls = _traced(tmp_path, "convert", str(cam), "--out-dir", str(out),
                                 *force, "--to", "iso-mill", "-j", jobs)
    for n in range(4):
        target = str(out / f"p{n}.nc")
        part = re.compile(rf'{re.escape(str(out))}/\.p{n}\.nc\.[0-9a-f]{{8}}\.part')
        synced = [i for i, (_, call) in enumerate(calls)
                  if call.startswith("fsync(") and part.search(call)]
        named = [i for i, (_, call) in enumerate(calls)
                 if re.match(r"(rename|link)", call) and target in call]
        removed = [i for i, (_, call) in enumerate(calls)
                   if call.startswith("unlink") and part.search(call)]
        assert len(synced) == 1 and len(named) == 1 and synced[0] < named[0], (n, calls)
        assert calls[named[0]][1].startswith("rename" if jobs == "2" else "link")
        assert jobs == "2" or len(removed) == 1 and named[0] < removed[0]
        assert calls[synced[0]][0] != main_thread and calls[named[0]][0] != main_thread
        assert (out / f"p{n}.nc").read_text() == PROGRAM.replace("X25.4", f"X25.{n}").replace(
            "G21", "G71")
    assert not list(out.glob(".*"))


@pytest.mark.parametrize("jobs", ["1", "2"])
def test_an_output_whose_commit_fails_is_that_files_error_and_leaves_nothing(tmp_path, jobs):
    """The fsync and rename run in the commit threads (tapegate.converting.Commits): a rename
    that fails (a folder holds the output's name) is its file's error at its turn, in its
    row, the others are written, and no temporary file is left."""
    cam = tmp_path / "cam"
    cam.mkdir()
    for n in range(6):
        (cam / f"p{n}.nc").write_text(PROGRAM.replace("X25.4", f"X25.{n}"))
    out = tmp_path / "out"
    (out / "p1.nc" / "x").mkdir(parents=True)  # a folder, not empty: no rename replaces it
    (out / "p4.nc" / "x").mkdir(parents=True)
    result = _run("convert", str(cam), "--out-dir", str(out), "--force", "--to", "iso-mill",
                  "--units", "inch", "-j", jobs)
    assert result.exit_code == 1
    said = result.stderr.splitlines()  # (a failed file's notes are dropped: its error alone)
    for n in range(6):
        mine = [line for line in said if line.startswith(f"{cam / f'p{n}.nc'}: ")]
        assert (mine == [f"{cam / f'p{n}.nc'}: Is a directory"] if n in (1, 4)
                else mine and all("Is a directory" not in line for line in mine))
    rows = [line.split() for line in result.stdout.splitlines()[2:-1]]
    assert [(row[0], row[-1]) for row in rows] == [
        (str(cam / f"p{n}.nc"), "FAILED" if n in (1, 4) else "ok") for n in range(6)]
    assert sorted(p.name for p in out.iterdir()) == [f"p{n}.nc" for n in range(6)]
    assert (out / "p5.nc").read_text() == ("%\nN1 G70 G90 G94\nN2 G01 X1.004 Y0.5 F10.\n"
                                           "N3 G02 X1.181 Y0.787 I0.197 J0\nM30\n%\n")
    assert (out / "p1.nc").is_dir() and not list(out.glob(".*"))


def test_commits_run_in_order_given_and_close_runs_every_one(tmp_path):
    """Commits: each output handed over gets its name, or its commit's error from its wait
    (its temporary file removed: a folder where the output would be; a name taken without
    --force, told as the conversion tells it); close runs every one handed over, and one
    handed over after close runs at once."""
    from formats.convert import Handover
    from formats.files import PendingFile
    from tapegate.converting import Commits

    out = tmp_path / "out"
    (out / "p3.nc" / "x").mkdir(parents=True)  # a folder, not empty: no rename replaces it
    (out / "p4.nc").write_text("kept\n")

    def output(n: int) -> Handover:
        pending = PendingFile(out, f"p{n}.nc")
        pending.write(f"program {n}\n".encode())
        target = out / f"p{n}.nc"
        return Handover(pending, target, n != 4, lambda: None,
                        lambda: OSError(f"{target} exists"))

    commits = Commits(1)
    handed = [commits.submit(output(n)) for n in range(6)]
    commits.close()
    assert all(c.done() for c in handed)
    errors = [c.wait() for c in handed]
    assert [str(e) for e in errors if e] == ["[Errno 21] Is a directory", f"{out}/p4.nc exists"]
    assert errors[3] is not None and errors[:3] == [None] * 3 and errors[5] is None
    assert [(out / f"p{n}.nc").read_text() for n in (0, 1, 2, 4, 5)] == [
        "program 0\n", "program 1\n", "program 2\n", "kept\n", "program 5\n"]
    late = commits.submit(output(7))
    assert late.done() and late.wait() is None
    assert (out / "p7.nc").read_text() == "program 7\n"
    assert sorted(p.name for p in out.iterdir()) == [f"p{n}.nc" for n in (0, 1, 2, 3, 4, 5, 7)]


def test_a_batch_not_on_a_terminal_does_not_import_the_progress_bar(tmp_path):
    """tqdm (18 ms of imports, before any worker starts) is loaded only to show the bar."""
    for n in range(2):
        (tmp_path / f"p{n}.nc").write_text(PROGRAM)
    code = ("import sys\nfrom tapegate.cli import main\n"
            "try:\n    main(sys.argv[1:], prog_name='tapegate')\nexcept SystemExit as end:\n"
            "    print('tqdm' in sys.modules, end.code, file=sys.stderr)\n")
    done = subprocess.run([sys.executable, "-c", code, "convert", str(tmp_path), "--out-dir",
                           str(tmp_path / "out"), "--to", "iso-mill", "-j", "2"],
                          capture_output=True, text=True, cwd=ROOT, timeout=120, check=False)
    assert done.stderr.splitlines()[-1] == "False 0", done.stderr
    assert (tmp_path / "out" / "p1.nc").read_text() == PROGRAM.replace("G21", "G71")


def _threads(pid: int) -> int:
    return len(list(Path(f"/proc/{pid}/task").iterdir()))


def _long_check(tmp_path: Path) -> tuple[Path, Path, Path]:
    """A folder of 400 copies of a short program, each repeated 400 times, some seconds of a
    `check -j 2` given it four times (800 files of 20 copies were checked in 0.12 s, and
    under the suite's load the whole check could end before a signal reached it); an empty
    TMPDIR for the check; the `tapegate` command."""
    program = (Path(__file__).resolve().parents[1] / "tapegate" / "examples" / "bracket.nc")
    folder = tmp_path / "cam"
    folder.mkdir()
    body = program.read_text()
    for i in range(400):
        (folder / f"p{i}.nc").write_text(body * 400)
    scratch = tmp_path / "tmp"
    scratch.mkdir()
    return folder, scratch, Path(sys.executable).with_name("tapegate")


@pytest.mark.skipif(not Path("/proc/self/task").exists(), reason="needs /proc")
def test_sigterm_stops_the_threads_and_leaves_nothing_behind(tmp_path):
    """A CI job's timeout sends SIGTERM: `check -j 2` exits 143 at once (a thread sending
    findings stops, one in the core at its chunk's end), starts no process, and leaves no
    temporary file."""
    folder, scratch, exe = _long_check(tmp_path)
    proc = subprocess.Popen([str(exe), "check", *[str(folder)] * 4, "-p", "fanuc-mill",
                             "-j", "2"], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            env={**os.environ, "TMPDIR": str(scratch)})
    try:
        assert proc.stdout is not None
        proc.stdout.readline()  # findings are coming: the threads run
        # the main thread, which checks files too, and one more: no third thread waiting
        assert _threads(proc.pid) == 2
        tasks = list(Path(f"/proc/{proc.pid}/task").iterdir())
        assert all(not (task / "children").read_text().split() for task in tasks
                   if (task / "children").exists())  # no worker process
        started = time.monotonic()
        proc.terminate()
        _, err = proc.communicate(timeout=30)  # (the rest of what it wrote before it stopped)
        assert proc.returncode == 143, err
        assert time.monotonic() - started < 10
        assert b"Traceback" not in err
    finally:
        if proc.poll() is None:
            proc.kill()
    assert list(scratch.iterdir()) == []


def test_a_thread_whose_item_is_not_due_spills_its_text_and_goes_on(tmp_path, monkeypatch):
    """A report's text pieces of items not yet due go, past WAITING of them a thread (the
    items together), to a temporary file each: the threads finish items 1 and 2 while item 0
    is still running, 3 * WAITING pieces of the two stay in memory (3 threads), and every
    piece comes out in order."""
    import threading

    import tapegate.workers as workers

    maps: list[workers._Map] = []

    class Recorded(workers._Map):
        def __init__(self, *args: Any) -> None:
            super().__init__(*args)
            maps.append(self)

    monkeypatch.setattr(workers, "_Map", Recorded)
    flag = tmp_path / "first-may-end"
    finished = threading.Event()
    held: list[int] = []

    def slow_first(item: int) -> int:
        if item == 0:
            _wait_for(flag)
            return 0
        for n in range(5 * PIECES):
            # not ASCII: the spill keeps every character; bytes (a JSON report's, from the
            # core) come back as bytes, strings as strings
            piece = f"{item}:{n}:" + "é" * n
            send(piece.encode() if n % 3 == 0 else piece)
        if item == 2:
            finished.set()
        return item

    def release() -> None:
        if finished.wait(timeout=30):  # items 1 and 2 ended while item 0 ran
            with maps[0].cond:
                held.append(sum(len(slot.pieces) for slot in maps[0].slots.values()))
                held.append(maps[0].held)
                held.append(sum(slot.spill is not None for slot in maps[0].slots.values()))
        flag.touch()

    threading.Thread(target=release).start()
    pieces: list[str | bytes] = []
    assert list(ordered_map(slow_first, [0, 1, 2], 3, receive=pieces.append)) == [0, 1, 2]
    assert 5 * PIECES > 3 * WAITING  # (each item spills)
    assert held == [3 * WAITING, 3 * WAITING, 2]
    assert maps[0].held == 0  # (each item's pieces left the count as its turn came)
    assert pieces == [(f"{i}:{n}:" + "é" * n).encode() if n % 3 == 0 else f"{i}:{n}:" + "é" * n
                      for i in (1, 2) for n in range(5 * PIECES)]


def test_the_files_that_would_end_a_batch_alone_are_started_first(monkeypatch):
    """first(): a file larger than the mean whose work is more than the rest after it can
    share (with 2 threads: more than all the files after it), the largest first; a batch of
    equal files keeps its order; at most WINDOW a thread."""
    assert first([10] * 200, 2) == []
    assert first([1, 1, 100, 1], 2) == [2]
    assert first([1, 1, 100, 1], 1) == []
    assert first([5, 60, 1, 40, 1], 2) == [1, 3]  # 60 > 42 after it, 40 > 1
    # 40 is not more than the 41 after it, nor 30 than 81, but 3 times them is (4 threads:
    # the other 3 share what comes after); the largest first, the earlier of equal ones
    assert first([5, 30, 40, 1, 40], 2) == [4]
    assert first([5, 30, 40, 1, 40], 4) == [2, 4, 1]
    growing = [2 ** n for n in range(40)]  # each more than all those before it
    assert first(growing, 2) == [39]
    assert first(growing[::-1], 2) == [0, 1, 2, 3, 4]  # the others are below the mean
    assert first([], 2) == []
    tail = [1, 1, 1, 1, 1, 1, 100, 40, 20]
    assert first(tail, 2) == [6, 7, 8]
    import tapegate.workers as workers

    monkeypatch.setattr(workers, "WINDOW", 1)  # at most WINDOW a thread
    assert first(tail, 2) == [6, 7]


def test_a_long_last_item_starts_first_and_its_pieces_come_at_its_turn():
    """The item first() names is given out before the others: with two threads it has
    started before the third item does; every piece and result still comes in the items'
    order, the early item's text past WAITING pieces spilled meanwhile."""
    import threading

    started: list[int] = []
    lock = threading.Lock()

    def work(item: int) -> int:
        with lock:
            started.append(item)
        for n in range(3 * PIECES if item == 9 else 2):
            send(f"{item}.{n};")
        return item

    got: list[object] = []
    sizes = [1] * 9 + [100]
    for result in ordered_map(work, list(range(10)), 2, receive=got.append, sizes=sizes):
        got.append(result)
    assert started.index(9) < 2  # started among the first two
    expected: list[object] = []
    for item in range(10):
        expected.extend(f"{item}.{n};" for n in range(3 * PIECES if item == 9 else 2))
        expected.append(item)
    assert got == expected


def _long_last(tmp_path: Path) -> Path:
    """A folder whose last file is most of its work, with more findings than a thread holds
    in memory for a file not yet due (so its report is spilled)."""
    cam = tmp_path / "cam"
    cam.mkdir()
    for n in range(12):
        (cam / f"a{n:02d}.nc").write_text(ODD.replace("X20.", f"X2{n}."))
    body = "".join(f"N{n} X{n}. G01 F100.\nN{n} G77 X20.\n" for n in range(1, 6000))
    (cam / "z-long.nc").write_text(f"%\n{body}M30\n%\n")
    return cam


@pytest.mark.parametrize("fmt", ["text", "json", "jsonl"])
def test_a_long_last_file_started_first_is_reported_in_its_place(tmp_path, fmt):
    cam = _long_last(tmp_path)
    from tapegate.workers import file_sizes

    files = input_files([str(cam)])
    assert first(file_sizes(files), 2) == [len(files) - 1]
    # --all: the long file repeats its rules thousands of times, which the text report folds
    args = ["check", str(cam), "-p", "fanuc-mill", "--format", fmt, "--stats", "--all"]
    one, two = _run(*args, "-j", "1"), _run(*args, "-j", "2")
    assert one.exit_code == 1
    assert (two.exit_code, two.stdout, two.stderr) == (one.exit_code, one.stdout, one.stderr)
    assert len(one.stdout) > 4 * 64 * 1024  # more than WAITING slices of 64 KiB
    assert one.stdout.rindex("z-long.nc") > one.stdout.rindex("a11.nc")
    if fmt == "text":  # folded, the same whatever -j is, its fold lines in the file's place
        one, two = (_run(*args[:-1], "-j", jobs) for jobs in ("1", "2"))
        assert (two.exit_code, two.stdout, two.stderr) == (one.exit_code, one.stdout, one.stderr)
        assert one.stdout.rindex("z-long.nc") > one.stdout.rindex("a11.nc")
        assert "more like this" in one.stdout.split("z-long.nc", 1)[1]


def test_a_long_last_file_started_first_converts_as_in_one_thread(tmp_path):
    cam = _long_last(tmp_path)
    outputs = {}
    for jobs in ("1", "2"):
        out = tmp_path / f"out{jobs}"
        result = _run("convert", str(cam), "--out-dir", str(out), "--from", "fanuc-mill",
                      "--to", "fanuc-mill", "--units", "inch", "-j", jobs)
        assert result.exit_code == 0, result.stderr
        outputs[jobs] = (result.stdout.replace(str(out), "OUT"), result.stderr,
                         {p.name: p.read_bytes() for p in sorted(out.iterdir())})
    assert outputs["1"] == outputs["2"]
    assert len(outputs["1"][2]) == 13


def _jobs_by_pathlib(inputs: list[str], output: str | None, out_dir: str | None,
                     dry_run: bool) -> list[tuple[str, str | None]] | str:
    """What convert's batch_jobs gave when it listed with pathlib (the pairs, or the usage
    error's message)."""
    import glob
    import pathlib

    files: list[tuple[pathlib.Path, pathlib.Path]] = []
    for name in inputs:
        path = pathlib.Path(name)
        if path.is_dir():
            files.extend((f, f.relative_to(path)) for f in sorted(path.rglob("*"))
                         if f.is_file() and not any(p.startswith(".") for p in
                                                    f.relative_to(path).parts))
        elif path.exists():
            files.append((path, pathlib.Path(path.name)))
        else:
            matches = [m for m in sorted(pathlib.Path(m) for m in glob.glob(name, recursive=True))
                       if m.is_file()]
            if not matches:
                return f"no such file or directory: {name}"
            files.extend((m, pathlib.Path(m.name)) for m in matches)
    if output and (len(files) != 1 or pathlib.Path(inputs[0]).is_dir()):
        return "-o names one output file; use --out-dir for several inputs"
    if output and out_dir:
        return "give -o or --out-dir, not both"
    if not (output or out_dir or dry_run):
        return "say where to write: -o FILE, --out-dir DIR, or --dry-run"
    jobs: list[tuple[str, str | None]] = []
    seen: set[pathlib.Path] = set()
    for path, relative in files:
        target = (None if dry_run else pathlib.Path(output) if output
                  else pathlib.Path(out_dir or ".") / relative)
        if target is not None:
            if target.resolve() == path.resolve():
                return f"{path}: the output would replace the input"
            if target in seen:
                return f"two inputs would both be written to {target}"
            seen.add(target)
        jobs.append((str(path), str(target) if target else None))
    return jobs


def test_a_conversion_lists_and_names_its_files_as_pathlib_did(tmp_path, monkeypatch):
    """convert's batch_jobs, written with os.path and each folder resolved once: the same
    files, names, outputs and refusals as with pathlib's objects, on a tree of links, hidden
    files, patterns, ``..``, and outputs that would replace an input (through a link too)."""
    from click import ClickException

    from tapegate.converting import batch_jobs

    cam = tmp_path / "cam"
    for folder in ("a/b", "a-c", ".git", "out"):
        (cam / folder).mkdir(parents=True)
    for name in ("a/b/x.nc", "a-c/y.nc", "a.nc", ".h.nc", ".git/q", "a/b.nc", "out/a.nc"):
        (cam / name).write_text(PROGRAM)
    (cam / "link.nc").symlink_to("a.nc")
    (cam / "linked").symlink_to("a")
    (cam / "to-out").symlink_to("out")
    monkeypatch.chdir(tmp_path)
    cases: list[tuple[list[str], str | None, str | None, bool]] = [
        (["cam"], None, "o", False), (["./cam/"], None, "./o//p/", False),
        ([str(cam)], None, str(tmp_path / "o"), False), (["cam/a"], None, ".", False),
        (["cam/../cam/a"], None, "o", False), (["cam"], None, None, True),
        (["cam/a.nc"], "x.nc", None, False), (["./cam//a.nc"], "./y/../x.nc", None, False),
        (["cam/a.nc"], "cam/link.nc", None, False), (["cam/a.nc"], "cam/a/../a.nc", None, False),
        (["cam/out"], None, "cam/to-out", False), (["cam/out"], None, "cam/out", False),
        (["cam/a/b.nc"], None, "cam/linked", False), (["cam/a"], None, "cam/linked", False),
        (["cam/a.nc", "cam/out/a.nc"], None, "o", False), (["cam/*.nc"], None, "o", False),
        (["cam/**/*.nc"], None, "o", False), (["cam/nope*.nc"], None, "o", False),
        (["cam"], "x.nc", None, False), (["cam/a.nc"], "x.nc", "o", False),
        (["cam/a.nc"], None, None, False), ([""], None, "o", False), (["cam"], None, "", True),
    ]
    for inputs, output, out_dir, dry_run in cases:
        try:
            ours: list[tuple[str, str | None]] | str = batch_jobs(inputs, output, out_dir,
                                                                  dry_run)
        except ClickException as exc:
            ours = exc.message
        assert ours == _jobs_by_pathlib(inputs, output, out_dir, dry_run), (inputs, output,
                                                                            out_dir)


def test_a_spill_file_has_no_name_and_is_made_in_the_temporary_folder(tmp_path, monkeypatch):
    """A spill file is made in ``$TMPDIR`` (the folder tempfile takes first) and has no name
    there from the start; a folder where it cannot be made (here: none) is tempfile's to
    replace, and the file works all the same."""
    import tapegate.workers as workers

    monkeypatch.setenv("TMPDIR", str(tmp_path))
    fd, folder = workers._spill_file()
    assert folder == str(tmp_path)
    try:
        assert os.pwrite(fd, "é".encode(), 0) == 2
        assert workers._read(fd, 2, 0).decode() == "é"
        assert list(tmp_path.iterdir()) == []
        if hasattr(os, "O_TMPFILE"):  # made in the folder itself (its file system's device)
            assert os.fstat(fd).st_dev == os.stat(tmp_path).st_dev
    finally:
        os.close(fd)
    monkeypatch.setenv("TMPDIR", str(tmp_path / "missing"))
    fd, folder = workers._spill_file()
    assert folder != str(tmp_path / "missing")  # (tempfile's choice)
    try:
        assert os.pwrite(fd, b"x", 0) == 1 and workers._read(fd, 1, 0) == b"x"
    finally:
        os.close(fd)
    assert list(tmp_path.iterdir()) == []


def test_sigterm_exits_while_the_threads_run_and_its_handler_is_put_back_after():
    """In the main thread, SIGTERM's handler while the threads run ends the map with exit
    status 128 + 15; the handler before it (here a function of the caller's) is put back
    when the map ends, whether it ends by its last item or by the signal."""
    import signal

    def mine(signum: int, frame: object) -> None:
        raise AssertionError("the map's own handler was to answer")

    before = signal.signal(signal.SIGTERM, mine)
    try:
        assert list(ordered_map(lambda n: n * 2, [1, 2, 3], 2)) == [2, 4, 6]
        assert signal.getsignal(signal.SIGTERM) is mine
        got = []
        with pytest.raises(SystemExit) as stopped:  # (the handler runs in this thread, at once)
            for n in ordered_map(lambda n: n, list(range(200)), 2):
                got.append(n)
                if n == 0:
                    os.kill(os.getpid(), signal.SIGTERM)
        assert stopped.value.code == 128 + signal.SIGTERM and got == [0]
        assert signal.getsignal(signal.SIGTERM) is mine
    finally:
        signal.signal(signal.SIGTERM, before)


def test_sighup_made_an_exit_is_held_as_sigterm_is_while_the_threads_run():
    """Review 44, finding 8: a command that writes files makes SIGHUP an exit
    (formats.files.exit_on_termination) raised wherever the main thread is; among the map's
    locks that hung 2 of 140 stopped batches. While the threads run the map answers it as it
    answers SIGTERM (an exit with 128 + 1 at a safe point), and puts the handler back."""
    import signal

    from formats import files

    before = signal.signal(signal.SIGHUP, signal.SIG_DFL)
    term = signal.getsignal(signal.SIGTERM)
    try:
        files.exit_on_termination()
        made = signal.getsignal(signal.SIGHUP)
        assert made is files._exit_signalled
        got = []
        with pytest.raises(SystemExit) as stopped:
            for n in ordered_map(lambda n: n, list(range(200)), 2):
                got.append(n)
                if n == 0:
                    assert signal.getsignal(signal.SIGHUP) is not made  # the map's own
                    os.kill(os.getpid(), signal.SIGHUP)
        assert stopped.value.code == 128 + signal.SIGHUP and got == [0]
        assert signal.getsignal(signal.SIGHUP) is made
    finally:
        signal.signal(signal.SIGHUP, before)
        signal.signal(signal.SIGTERM, term)


def test_an_item_started_early_spills_past_early_pieces_and_leaves_the_budget_to_the_others(
        tmp_path, monkeypatch):
    """The item started first for its size (first()) waits longest for its turn: it holds
    EARLY pieces in memory and spills the rest, while an item near its turn keeps all of its
    pieces in memory within the budget (2 threads: 2 * WAITING)."""
    import threading

    import tapegate.workers as workers

    maps: list[workers._Map] = []

    class Recorded(workers._Map):
        def __init__(self, *args: Any) -> None:
            super().__init__(*args)
            maps.append(self)

    monkeypatch.setattr(workers, "_Map", Recorded)
    flag = tmp_path / "first-may-end"
    finished = {1: threading.Event(), 2: threading.Event()}
    seen: list[tuple[int, bool, int, bool]] = []
    short = 2 * WAITING - 1  # within the budget

    def item(n: int) -> int:
        if n == 0:
            _wait_for(flag)
            return 0
        for k in range(5 * PIECES if n == 2 else short):
            send(f"{n}:{k}")
        finished[n].set()
        return n

    def release() -> None:
        if finished[1].wait(timeout=30) and finished[2].wait(timeout=30):
            with maps[0].cond:
                seen.extend((s.index, s.early, len(s.pieces), s.spill is not None)
                            for s in sorted(maps[0].slots.values(), key=lambda s: s.index)
                            if s.index)
        flag.touch()

    threading.Thread(target=release).start()
    pieces: list[str] = []
    assert list(ordered_map(item, [0, 1, 2], 2, receive=pieces.append,
                            sizes=[1, 1, 100])) == [0, 1, 2]
    assert seen == [(1, False, short, False), (2, True, EARLY, True)]
    assert pieces == [f"1:{k}" for k in range(short)] + [f"2:{k}" for k in range(5 * PIECES)]
    assert maps[0].held == 0


def test_the_workers_condition_wakes_its_waiters_and_leaves_an_interrupted_one():
    """The workers' condition (on _thread's locks, as threading.Condition): a waiter holds the
    shared lock again when it returns; notify wakes one waiter, notify_all the rest; a wait
    ended by KeyboardInterrupt (^C in the main thread) holds the lock again and leaves no
    waiter behind, so a later notify wakes a real one."""
    import _thread
    import signal
    import threading

    import tapegate.workers as workers

    lock = _thread.allocate_lock()
    cond = workers._Condition(lock)
    woken: list[int] = []

    def waiter(n: int) -> None:
        with cond:
            cond.wait()
            assert lock.locked()
            woken.append(n)

    threads = [threading.Thread(target=waiter, args=(n,), daemon=True) for n in range(3)]
    for thread in threads:
        thread.start()
    deadline = time.monotonic() + 30
    while True:
        with cond:
            if len(cond._waiters) == 3:
                cond.notify()
                break
        assert time.monotonic() < deadline, "the three waiters never waited"
        time.sleep(0.001)
    deadline = time.monotonic() + 30
    while not woken and time.monotonic() < deadline:
        time.sleep(0.01)
    assert len(woken) == 1
    with cond:
        assert len(cond._waiters) == 2
        cond.notify_all()
    for thread in threads:
        thread.join(timeout=30)
    assert sorted(woken) == [0, 1, 2]

    # ^C once the main thread waits (its waiter seen in the queue), never before it; if the
    # wait is not ended by it, a notify after 30 s ends the test with a failure, not a hang
    stop = threading.Event()
    sent: list[bool] = []

    def interrupt() -> None:
        deadline = time.monotonic() + 30
        while not stop.is_set() and time.monotonic() < deadline:
            if cond._waiters:
                time.sleep(0.05)  # the waiter is queued just before the wait's acquire
                sent.append(True)
                os.kill(os.getpid(), signal.SIGINT)
                break
            time.sleep(0.001)
        if stop.wait(30):
            return
        with cond:
            cond.notify_all()

    before = signal.signal(signal.SIGINT, signal.default_int_handler)
    sender = threading.Thread(target=interrupt, daemon=True)
    try:
        sender.start()
        with pytest.raises(KeyboardInterrupt), cond:
            try:
                cond.wait()
            finally:
                assert lock.locked()  # taken back before the interrupt goes on
        assert sent == [True]
        assert not lock.locked() and not cond._waiters
    finally:
        stop.set()
        sender.join(timeout=30)
        signal.signal(signal.SIGINT, before)


@pytest.mark.parametrize("folder", [".", "/", "//", "a", "/a/b", "//a", "..", "../x"])
def test_a_path_below_a_folder_is_joined_as_os_path_joins_it(folder):
    """formats.files.joined, written out: os.path.join's path for a folder as pure() writes
    it (the root "/" and "//" the only ones ending in a slash) and a relative path below it."""
    import formats.files as files

    assert files.pure(folder) == folder
    for below in ("p.nc", "d/p.nc", "..nc"):
        assert files.joined(folder, below) == (below if folder == "." else
                                               os.path.join(folder, below))


def test_a_thread_failing_outside_an_items_function_is_raised_not_waited_for(monkeypatch):
    """An error a worker meets in the map's own work (not in ``func``), after it has taken an
    item: the main thread raises it where it would wait for that item, after handing on the
    items done before it, and does not wait for ever (review 25)."""
    import tapegate.workers as workers

    real = workers._Map.work
    calls: list[int] = []

    def work(self):  # type: ignore[no-untyped-def]
        calls.append(1)
        if len(calls) == 1:  # the first thread: one item taken, then the error
            with self.cond:
                self.slots[self.order[self.given]] = workers._Slot(self.order[self.given], False)
                self.given += 1
            raise MemoryError("outside the item's function")
        real(self)

    monkeypatch.setattr(workers._Map, "work", work)
    got: list[object] = []
    error: list[BaseException] = []

    def run() -> None:
        try:
            for result in workers.ordered_map(lambda x: x * 10, [1, 2, 3, 4], 2):
                got.append(result)
        except BaseException as exc:  # noqa: BLE001 - the test reads it below
            error.append(exc)

    import threading

    thread = threading.Thread(target=run, daemon=True)
    thread.start()
    thread.join(timeout=60)
    assert not thread.is_alive(), "the main thread waited for ever for the failed thread's item"
    assert len(error) == 1 and isinstance(error[0], MemoryError)
    assert str(error[0]) == "outside the item's function"
    assert got == []  # item 0 was the failed thread's: nothing after it is handed on


# -- the main thread as a worker (sizes given: a function that sends text or nothing) --------


def _worker_takes_item_zero(monkeypatch: pytest.MonkeyPatch) -> None:
    """The main thread's first look for item 0 waits (20 s at most) until the thread it
    started has been given item 0, so that the main thread's own items are not yet due."""
    import tapegate.workers as workers

    take = workers._Map.take

    def later(self: workers._Map, index: int, here: bool = False) -> Any:
        if index == 0 and here:
            deadline = time.monotonic() + 20.0
            while 0 not in self.slots and time.monotonic() < deadline:
                time.sleep(0.001)
        return take(self, index, here)

    monkeypatch.setattr(workers._Map, "take", later)


def test_the_main_thread_does_items_while_the_due_one_runs_and_keeps_their_order(
        monkeypatch):
    """With sizes given, `-j 2` starts one thread and the main thread works too: while the
    other thread's item 0 runs, the main thread does items 1-3 itself; their text pieces wait
    (past the budget in a temporary file), and every piece reaches receive in the items'
    order, before its item's result."""
    import _thread
    import threading

    import tapegate.workers as workers

    _worker_takes_item_zero(monkeypatch)
    spills: list[int] = []
    spill_file = workers._spill_file

    def counted() -> tuple[int, str]:
        spills.append(1)
        return spill_file()

    monkeypatch.setattr(workers, "_spill_file", counted)
    main_thread = _thread.get_ident()
    by: dict[int, int] = {}
    done_here = threading.Event()

    def func(item: int) -> int:
        by[item] = _thread.get_ident()
        if item == 0 and not done_here.wait(timeout=30):
            raise AssertionError("the main thread did not do items 1-3 while item 0 ran")
        for n in range(2 * PIECES):  # past the budget of the items not due (2 * WAITING)
            piece = f"{item}:{n}:" + "é" * n
            send(piece.encode() if n % 2 else piece)
        if item == 3 and by.get(1) == by.get(2) == by.get(3) == main_thread:
            done_here.set()
        return item

    got: list[object] = []
    items = list(range(8))
    for result in ordered_map(func, items, 2, receive=got.append, sizes=[1] * len(items)):
        got.append(result)
    expected: list[object] = []
    for item in items:
        expected.extend((f"{item}:{n}:" + "é" * n).encode() if n % 2 else f"{item}:{n}:" + "é" * n
                        for n in range(2 * PIECES))
        expected.append(item)
    assert got == expected
    assert by[0] != main_thread
    assert by[1] == by[2] == by[3] == main_thread
    assert 3 * 2 * PIECES > 2 * WAITING and spills  # (the main thread's items spilled)


def test_the_due_item_done_by_the_main_thread_is_received_at_once():
    """An item given to the main thread at its turn (every item before it taken) hands its
    pieces to receive as it sends them, as with one job; one given before its turn keeps
    them in its slot, for its turn (the map's own take)."""
    import tapegate.workers as workers

    events: list[object] = []

    def func(item: int) -> int:
        send((item, "sent"))
        events.append((item, "after send"))
        return item

    state = workers._Map(func, [0, 1, 2], 16, 32)
    with state.cond:
        due, later = state._give(), state._give()
    assert (due.index, later.index, state.due) == (0, 1, 0)
    state.here(later, events.append)  # not due: kept
    assert events == [(1, "after send")] and list(later.pieces) == [(1, "sent")]
    assert later.done and later.result == 1
    state.here(due, events.append)  # due: received at once
    assert events[1:] == [(0, "sent"), (0, "after send")] and not due.pieces
    assert due.done and due.result == 0
    assert state.take(0) == ([], due, None)  # its turn: nothing more to hand on
    assert state.take(1) == ([(1, "sent")], later, None)
    # and in a whole map, every piece in order before its item's result
    got: list[object] = []
    for result in ordered_map(_sends, list(range(30)), 2, receive=got.append,
                              sizes=[1] * 30):
        got.append(result)
    assert got == _sent_in_order(30)


def test_an_exception_in_the_main_threads_item_is_raised_at_its_turn(monkeypatch):
    """The main thread's own item 1 raises while the other thread's item 0 runs: it is raised
    at item 1's turn, after item 0's pieces and result and item 1's own piece."""
    import _thread
    import threading

    _worker_takes_item_zero(monkeypatch)
    main_thread = _thread.get_ident()
    raised = threading.Event()

    def func(item: int) -> int:
        if item == 0 and not raised.wait(timeout=30):
            raise AssertionError("item 1 was not done while item 0 ran")
        send(f"piece of {item}")
        if item == 1:
            assert _thread.get_ident() == main_thread
            raised.set()
            raise OSError("item 1 is bad")
        return item

    got: list[object] = []
    with pytest.raises(OSError, match="item 1 is bad"):
        for result in ordered_map(func, list(range(20)), 2, receive=got.append,
                                  sizes=[1] * 20):
            got.append(result)
    assert got == ["piece of 0", 0, "piece of 1"]


def test_an_interrupt_in_the_main_threads_item_stops_the_map_at_once(monkeypatch):
    """^C (KeyboardInterrupt) in an item the main thread does is not kept for its turn: it
    leaves the map at once, and the other thread, sending, stops before the map returns."""
    import _thread
    import threading

    _worker_takes_item_zero(monkeypatch)
    main_thread = _thread.get_ident()
    interrupted = threading.Event()
    stopped: list[str] = []

    def func(item: int) -> int:
        if item == 0:
            try:
                if not interrupted.wait(timeout=30):
                    raise AssertionError("item 1 was not done in the main thread")
                deadline = time.monotonic() + 30.0
                while time.monotonic() < deadline:  # sends until the map stops it
                    send("more of 0")
                    time.sleep(0.001)
            except BaseException as exc:
                stopped.append(type(exc).__name__)
                raise
            return 0
        if _thread.get_ident() == main_thread:
            interrupted.set()
            raise KeyboardInterrupt
        return item

    started = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        list(ordered_map(func, list(range(20)), 2, receive=lambda piece: None,
                         sizes=[1] * 20))
    assert time.monotonic() - started < 20
    assert stopped == ["_Stopped"]  # the other thread ended before the map returned


@pytest.mark.skipif(not Path("/proc/self/task").exists(), reason="needs /proc")
def test_ctrl_c_while_the_main_thread_checks_ends_the_check_cleanly(tmp_path):
    """^C (SIGINT) of `check -j 2` while both threads check, the main thread among them,
    most of its time in the core: "Aborted!" and exit 1 as with one job, at once, without a
    traceback or a temporary file left."""
    import signal

    folder, scratch, exe = _long_check(tmp_path)
    # (SIGINT set back to its default in the child: a suite run in the background of a
    # shell without job control ignores SIGINT, the child inherits that, and Python then
    # installs no KeyboardInterrupt: the check ran to its end)
    proc = subprocess.Popen([str(exe), "check", *[str(folder)] * 4, "-p", "fanuc-mill",
                             "-j", "2"], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            env={**os.environ, "TMPDIR": str(scratch)},
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    try:
        assert proc.stdout is not None
        proc.stdout.readline()  # findings are coming: the threads run
        assert _threads(proc.pid) == 2
        started = time.monotonic()
        proc.send_signal(signal.SIGINT)
        _, err = proc.communicate(timeout=30)
        assert proc.returncode == 1, err
        assert err.endswith(b"Aborted!\n"), err
        assert time.monotonic() - started < 10
        assert b"Traceback" not in err
    finally:
        if proc.poll() is None:
            proc.kill()
    assert list(scratch.iterdir()) == []


def test_the_main_thread_leaves_the_items_started_early_to_the_threads():
    """The items started early (first()) are long: the main thread, which hands the reports
    on, does not take one (the window would not move meanwhile); it waits until a thread has
    taken the last of them, is woken by that thread, and takes the first of the others."""
    import threading

    import tapegate.workers as workers

    state = workers._Map(lambda item: item, list(range(10)), 16, 32, [9])
    state.threads = 1  # (-j 2: one thread beside the main thread)
    got: list[Any] = []
    main = threading.Thread(target=lambda: got.append(state.take(0, True)), daemon=True)
    main.start()
    main.join(timeout=0.3)
    assert main.is_alive() and not got  # waiting: the one item it may be given is early
    given: list[Any] = []
    # a thread's work: it takes item 9, then item 0 is taken by the main thread; the thread
    # then waits in vain for the window (16 items from 0, all given): stopped below
    worker = threading.Thread(target=lambda: given.append(state.work()), daemon=True)

    def func(item: int) -> int:
        given.append(item)
        deadline = time.monotonic() + 20.0
        while item == 9 and not got and time.monotonic() < deadline:
            time.sleep(0.001)  # (the early item runs until the main thread has its own)
        return item

    state.func = func
    worker.start()
    main.join(timeout=20)
    assert got, "the main thread was not woken once the early item was taken"
    pieces, slot, own = got[0]
    assert pieces == [] and slot is None and own.index == 0 and not own.early
    state.stop()
    worker.join(timeout=20)
    assert not worker.is_alive()
    assert given[0] == 9  # the thread's first item: the early one


def test_the_main_thread_takes_an_early_item_once_every_thread_has_one():
    """Review 34, finding 3: at -j 2 (one thread) with two long files started early, the
    main thread left both to the thread, which ran them one after the other (a model with
    sleeps: 0.90 s against 0.55 s). Once every thread has an early item, the main thread is
    woken and takes the next early one itself."""
    import threading

    import tapegate.workers as workers

    state = workers._Map(lambda item: item, list(range(10)), 16, 32, [8, 9])
    state.threads = 1
    got: list[Any] = []
    main = threading.Thread(target=lambda: got.append(state.take(0, True)), daemon=True)
    main.start()
    main.join(timeout=0.3)
    assert main.is_alive() and not got  # no thread has an early item yet
    given: list[Any] = []

    def func(item: int) -> int:
        given.append(item)
        deadline = time.monotonic() + 20.0
        while item == 8 and not got and time.monotonic() < deadline:
            time.sleep(0.001)  # (the thread's early item runs until the main thread has one)
        return item

    state.func = func
    worker = threading.Thread(target=lambda: state.work(), daemon=True)
    worker.start()
    main.join(timeout=20)
    assert got, "the main thread was not woken once the thread had its early item"
    pieces, slot, own = got[0]
    assert pieces == [] and slot is None and own.index == 9 and own.early
    assert given[0] == 8
    state.stop()
    worker.join(timeout=20)
    assert not worker.is_alive()


def test_two_long_files_at_the_end_run_side_by_side_at_j_2():
    """The whole map at -j 2 with two long items started early (20 short ones, then 50 and
    40 units): the main thread does one of the long ones, so both are in hand at once --
    each is started before the other ends -- and every result comes in input order."""
    import tapegate.workers as workers

    sizes = [1] * 20 + [50, 40]
    spans: dict[int, tuple[float, float]] = {}

    def func(item: int) -> int:
        start = time.monotonic()
        time.sleep(sizes[item] * 0.002)
        spans[item] = (start, time.monotonic())
        return item

    out = list(workers.ordered_map(func, list(range(len(sizes))), 2, sizes=sizes))
    assert out == list(range(len(sizes)))
    (a0, a1), (b0, b1) = spans[20], spans[21]
    assert a0 < b1 and b0 < a1  # the two long ones overlapped


_STUCK = """
import os, sys
from tapegate.workers import ordered_map

read_end, write_end = os.pipe()  # (the write end held here: a read of it never ends)


def work(item):
    if item == 0:
        print("stuck", flush=True)
        os.read(read_end, 1)  # in the system, the GIL released: no stop reaches it
    return item


for result in ordered_map(work, [0, 1, 2], 2):
    pass
"""


def test_a_second_ctrl_c_ends_the_join_of_a_thread_that_never_returns(tmp_path):
    """The first ^C stops the map and the main thread joins its threads; a thread that never
    comes back (a read that never ends) held the join for good, and every later ^C was held
    for a safe point that never came (review 42, finding 6). The join is such a point: the
    next ^C ends the process (KeyboardInterrupt), the stopped daemon threads left. SIGINT is
    sent until the process ends (the first may land before the main thread waits), with a
    time limit."""
    import signal

    proc = subprocess.Popen([sys.executable, "-c", _STUCK], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, cwd=ROOT,
                            env={**os.environ, "PYTHONPATH": str(ROOT)},
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    try:
        assert proc.stdout is not None
        assert proc.stdout.readline() == b"stuck\n"
        sent, started = 0, time.monotonic()
        while proc.poll() is None and time.monotonic() - started < 30:
            proc.send_signal(signal.SIGINT)
            sent += 1
            with contextlib.suppress(subprocess.TimeoutExpired):
                proc.wait(timeout=0.2)
        _, err = proc.communicate(timeout=10)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    assert proc.returncode in (-signal.SIGINT, 128 + signal.SIGINT, 1), err
    assert b"KeyboardInterrupt" in err and sent >= 2, (sent, err)


def _full(*args: object) -> OSError:
    import errno

    return OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), *args)


def _mapped_within(seconds: float, *args: Any, **kwargs: Any) -> list[object]:
    """ordered_map's pieces and results, in the order received, from a thread of its own
    (without the signal handlers of the main thread's map), which must end in ``seconds``:
    a map whose threads all wait would otherwise hang the test."""
    import threading

    got: list[object] = []
    failed: list[BaseException] = []

    def run() -> None:
        try:
            for result in ordered_map(*args, receive=got.append, **kwargs):
                got.append(result)
        except BaseException as exc:
            failed.append(exc)

    thread = threading.Thread(target=run, daemon=True)
    thread.start()
    thread.join(seconds)
    assert not thread.is_alive(), "the map hung"
    if failed:
        raise failed[0]
    return got


def _pieces_of(item: int) -> int:
    return 3 * PIECES if item % 3 == 0 else 2


def _sending(item: int) -> int:
    if item == 0:  # (the items after it done meanwhile: their pieces wait, past the budget)
        time.sleep(0.3)
    for n in range(_pieces_of(item)):
        piece = f"{item}:{n}:" + "é" * (n % 7)
        send(piece.encode() if n % 2 else piece)
    return item


def _expected_pieces(items: list[int]) -> list[object]:
    expected: list[object] = []
    for item in items:
        expected.extend((f"{item}:{n}:" + "é" * (n % 7)).encode() if n % 2
                        else f"{item}:{n}:" + "é" * (n % 7) for n in range(_pieces_of(item)))
        expected.append(item)
    return expected


@pytest.mark.parametrize("jobs", [2, 3])
@pytest.mark.parametrize("early", [False, True])
def test_a_spill_that_cannot_be_made_loses_no_piece(monkeypatch, capfd, jobs, early):
    """Review 75, N1: where no spill file can be made (a full temporary folder, no descriptor
    left), every item's pieces still come in order, with the map's threads waiting for their
    items' turn (items started early among them: no thread waits for ever) and the main
    thread's own item holding its pieces; said at most once on stderr, naming the folder."""
    import tapegate.workers as workers

    def no_room() -> tuple[int, str]:
        raise _full("/full")

    monkeypatch.setattr(workers, "_spill_file", no_room)
    monkeypatch.setattr(workers, "WAITING", 1)  # (every item past its first piece would spill)
    items = list(range(40))
    sizes = [1] * len(items)
    if early:  # long ones late in the batch, started first (first())
        for index in (30, 33, 36, 39):
            sizes[index] = 200
    got = _mapped_within(60, _sending, items, jobs, sizes=sizes)
    assert got == _expected_pieces(items)
    told = [line for line in capfd.readouterr().err.splitlines() if line]
    assert told in ([], ["tapegate: cannot write the reports waiting for their turn to /full: "
                         "No space left on device; the files wait for their turn instead"]), told


def test_the_main_threads_item_whose_spill_fails_is_done_again_at_its_turn(monkeypatch, capfd):
    """Issue 35's leftover of review 75, N1: the main thread's own item, begun before its turn,
    cannot wait for room (only that thread makes it), so when the spill failed it held its
    whole report in memory (a 38 MB report, 38 MB). Now it is abandoned there, its pieces
    dropped, and done again at its turn, its pieces then handed on at once: memory flat, every
    piece once and in order, told once.

    Two long items last (10: 300, 11: 100; first() starts them early, 10 the larger): the
    thread takes 10, and works on it until 11 is begun, which the main thread does, before
    its turn (it takes an early item once every thread has one). Item 11 sends 80 pieces; no
    spill file can be made; WAITING 1: a budget of 2 pieces for the items not due. Before,
    the pieces held by the items not due peaked at 79-80 (item 11's); now at most the
    budget, 2, plus an early item's EARLY (2) each: 6."""
    import threading

    import tapegate.workers as workers

    def no_room() -> tuple[int, str]:
        raise _full("/full")

    monkeypatch.setattr(workers, "_spill_file", no_room)
    monkeypatch.setattr(workers, "WAITING", 1)
    calls: list[int] = []
    peak = [0]
    put = workers._Map.put

    def watched(self: Any, slot: Any, piece: Any, here: bool = False) -> None:
        put(self, slot, piece, here)
        with self.cond:
            held = sum(len(s.pieces) + s.kept for i, s in self.slots.items() if i != self.due)
        peak[0] = max(peak[0], held)

    monkeypatch.setattr(workers._Map, "put", watched)
    lock = threading.Lock()
    started = threading.Event()

    def sending(item: int) -> int:
        with lock:
            calls.append(item)
        if item == 11:
            started.set()
        elif item == 10:  # (its thread busy until 11 is begun: by the main thread)
            assert started.wait(30)
        for n in range(80 if item == 11 else 2):
            send(f"{item}:{n}")
        return item

    items = list(range(12))
    got = _mapped_within(60, sending, items, 2, sizes=[1] * 10 + [300, 100])
    expected: list[object] = []
    for item in items:
        expected.extend(f"{item}:{n}" for n in range(80 if item == 11 else 2))
        expected.append(item)
    assert got == expected
    assert peak[0] <= 6, peak
    assert calls.count(11) == 2 and calls.count(10) == 1  # (11 abandoned once, then again)
    told = [line for line in capfd.readouterr().err.splitlines() if line]
    assert told == ["tapegate: cannot write the reports waiting for their turn to /full: "
                    "No space left on device; the files wait for their turn instead"], told


def test_a_spill_that_fails_midway_keeps_the_pieces_after_those_spilled(monkeypatch):
    """A spill file whose writes fail once some pieces are in it (the disk full meanwhile):
    the pieces in the file come back first, then those held after them, in order."""
    import tapegate.workers as workers

    monkeypatch.setattr(workers, "WAITING", 1)
    writes = [0]
    pwrite = os.pwrite

    def filling(fd: int, data: bytes, at: int) -> int:
        writes[0] += 1
        if writes[0] > 6:
            raise _full()
        if writes[0] == 6:  # a short write, then no room: its part is never read
            return pwrite(fd, data[:1], at)
        return pwrite(fd, data, at)

    monkeypatch.setattr(os, "pwrite", filling)
    items = list(range(24))
    for jobs, sizes in ((2, None), (2, [1] * 24), (3, [1] * 20 + [50] * 4)):
        writes[0] = 0
        got = _mapped_within(60, _sending, items, jobs, sizes=sizes)
        assert got == _expected_pieces(items), (jobs, sizes)
        assert writes[0] > 6, (jobs, sizes)  # (the spill did fail)


_NO_ROOM = """
import errno, os, sys
import tapegate.workers as workers
from tapegate.launch import main

workers.WAITING = workers.EARLY = 0  # every piece of an item not due would spill
def no_room():
    raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), "/no-room")
workers._spill_file = no_room
sys.argv = ["tapegate", *sys.argv[1:]]
main(clean_exit=True)
"""


@pytest.mark.parametrize("fmt", ["text", "json"])
def test_check_whose_spill_has_no_room_reports_every_file_as_one_thread(tmp_path, fmt):
    """Review 75, N1: `check -j 2` whose report spill cannot be written (no room in the
    temporary folder) told files it had read as "cannot read FILE: No space left on device"
    (exit 2) and lost their findings. Now its output is -j 1's, byte for byte, with the same
    exit code; stderr is -j 1's, with at most one line more that says where the spill
    failed."""
    cam = _long_last(tmp_path)
    (cam / "m05.nc").write_text(ODD * 3)
    args = ["check", str(cam), "-p", "fanuc-mill", "--format", fmt, "--all"]
    runs = {jobs: subprocess.run([sys.executable, "-c", _NO_ROOM, *args, "-j", jobs],
                                 capture_output=True, cwd=ROOT, timeout=300, check=False,
                                 env={**os.environ, "PYTHONPATH": str(ROOT)})
            for jobs in ("1", "2")}
    one, two = runs["1"], runs["2"]
    assert one.returncode == 1, one.stderr
    assert (two.returncode, two.stdout) == (one.returncode, one.stdout)
    told = (b"tapegate: cannot write the reports waiting for their turn to /no-room: "
            b"No space left on device; the files wait for their turn instead\n")
    assert two.stderr.replace(told, b"", 1) == one.stderr, two.stderr[-2000:]
    assert b"cannot read" not in two.stderr and b"Traceback" not in two.stderr
    assert len(one.stdout) > 4 * 64 * 1024  # (more than the threads hold: it would spill)


def _small_files() -> None:
    """A child's files limited to 64 KiB (RLIMIT_FSIZE; a write past it fails with EFBIG,
    SIGXFSZ ignored): a temporary file that finds no room, without a full disk."""
    import resource
    import signal

    signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
    resource.setrlimit(resource.RLIMIT_FSIZE, (1 << 16, 1 << 16))


@pytest.mark.skipif(not hasattr(os, "O_TMPFILE"), reason="needs Linux")
def test_check_whose_spill_files_are_cut_short_reports_every_file_as_one_thread(tmp_path):
    """The spill's writes failing for real (no monkeypatch): every file of the child limited
    to 64 KiB, the spill of a long report fails midway with EFBIG. -j 2's report is -j 1's
    (which spills nothing), byte for byte, with its exit code; nothing is told as not read."""
    cam = _long_last(tmp_path)
    args = [sys.executable, "-m", "tapegate", "check", str(cam), "-p", "fanuc-mill",
            "--format", "jsonl", "--all"]
    runs = {jobs: subprocess.run([*args, "-j", jobs], capture_output=True, cwd=ROOT,
                                 timeout=300, check=False, preexec_fn=_small_files,
                                 env={**os.environ, "PYTHONPATH": str(ROOT),
                                      "TMPDIR": str(tmp_path)})
            for jobs in ("1", "2")}
    one, two = runs["1"], runs["2"]
    assert one.returncode == 1, one.stderr
    assert (two.returncode, two.stdout) == (one.returncode, one.stdout)
    assert len(one.stdout) > 4 * (1 << 16)  # (its spill, if any, is cut short)
    told = f"tapegate: cannot write the reports waiting for their turn to {tmp_path}: "
    lines = [line for line in two.stderr.decode().splitlines() if not line.startswith(told)]
    assert lines == one.stderr.decode().splitlines()
    assert "cannot read" not in two.stderr.decode()


def test_the_main_threads_own_item_never_waits_for_room_it_alone_makes(monkeypatch):
    """Other pieces than text (tuples) of the main thread's own item, not yet due, past every
    bound: held in memory, not waited with (only the main thread makes room, and waiting it
    waited for ever: the CI's hang in the whole map of the test above); every piece then
    reaches receive in the items' order."""
    import threading

    import tapegate.workers as workers

    _worker_takes_item_zero(monkeypatch)
    many = 4 * (workers.WAITING + workers.PIECES)
    sent = threading.Event()

    def func(item: int) -> int:
        if item == 0 and not sent.wait(timeout=30):
            raise AssertionError("item 1's pieces were not all sent while item 0 ran")
        for n in range(many if item == 1 else 2):
            send((item, n))
        if item == 1:
            sent.set()
        return item

    got: list[object] = []
    for result in ordered_map(func, list(range(4)), 2, receive=got.append, sizes=[1] * 4):
        got.append(result)
    expected: list[object] = []
    for item in range(4):
        expected += [(item, n) for n in range(many if item == 1 else 2)] + [item]
    assert got == expected
