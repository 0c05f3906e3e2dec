//! How an output file is written, one implementation for every caller: the temporary file
//! made and named (`formats.files.PendingFile`, for one file on the caller's thread, and
//! `Commits`, a batch's outputs named by threads of the core that never take the GIL), and
//! the temporary files a run leaves (^C) removed at its end.
//!
//! A temporary file is made by [`pending_file`]: a hidden `.HINT.XXXXXXXX.part` in the target
//! folder, created (never opened if it exists) with mode 0666 and the process's umask, and
//! entered in the process's list of temporary files in the same native step, so that no
//! moment exists (a `KeyboardInterrupt` is raised only between Python's steps) where the
//! file is there and the list does not name it. It leaves the list when it is named or
//! removed; [`sweep_pending`] removes what is left in it at the process's exit (the C
//! library's `exit`, after the interpreter's finalization, or `tapegate.launch.leave` before
//! its `os._exit`): a file not named by then never will be.
//!
//! The steps of one commit ([`commit`]), the same for one file and for a batch:
//!
//! 1. with `--force` and a regular file there, its owner, group and permission bits given
//!    to the temporary file ([`keep_access`]); the temporary file's data fsync'd (its
//!    descriptor, handed over: closed after);
//! 2. its name given: a rename over the target when it may be replaced (`--force`), else a
//!    hard link that fails if the name is taken (a file that appeared meanwhile is never
//!    replaced; on a file system without hard links, FAT and exFAT, a rename that fails if the
//!    name is taken: [`rename_no_replace`]) -- or, where a new version name is wanted, the first of `NAME`, `STEM.1.EXT`,
//!    `STEM.2.EXT`... that is free -- then the temporary name removed;
//! 3. on any failure, the temporary file removed: nothing is left but what was there before.
//!
//! Why the batch's run here: it ran them in Python threads (`tapegate.converting.Commits`),
//! each output's commit an fsync, a close, a stat and a rename or a link, each a system call
//! that dropped and took back the GIL, in threads woken by the disk's completions while the
//! converting threads wanted the GIL for their own files (docs/benchmarks.md, "the commits
//! without the GIL"). A commit there takes the GIL once, to be handed over (`submit`), and
//! once to be waited for (`wait`). One file's ([`commit_file`]) runs on the caller's thread,
//! the GIL released.
//!
//! The folder's fsync (the names on disk) stays the caller's (a batch's once per folder at
//! its end), and a target that is not a regular file (a device, a FIFO) is written into by
//! Python, never here.

use std::collections::{BTreeMap, HashMap, HashSet, VecDeque};
use std::ffi::{OsStr, OsString};
use std::fs::{self, File, OpenOptions};
use std::hash::{BuildHasher, Hasher};
use std::io;
use std::os::fd::{FromRawFd, IntoRawFd, RawFd};
use std::os::unix::ffi::{OsStrExt, OsStringExt};
use std::os::unix::fs::OpenOptionsExt;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Condvar, Mutex, MutexGuard, Once, PoisonError, TryLockError};
use std::thread::JoinHandle;

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

use crate::files::os_error;

/// One output handed over: its temporary file (open, owned here), its name, whether that name
/// may be replaced.
struct Job {
    ticket: u64,
    file: File,
    tmp: PathBuf,
    target: PathBuf,
    overwrite: bool,
}

/// What the threads and the callers share, under one lock.
#[derive(Default)]
struct State {
    queue: VecDeque<Job>,
    /// Each commit done and not yet waited for: its outcome.
    done: HashMap<u64, io::Result<()>>,
    /// The tickets handed out and not yet waited for.
    open: HashSet<u64>,
    next: u64,
    /// Threads waiting for a job.
    idle: usize,
    threads: usize,
    closed: bool,
}

#[derive(Default)]
struct Shared {
    state: Mutex<State>,
    /// A job queued, or the pool closed: for the threads.
    work: Condvar,
    /// A commit done: for a caller waiting for one.
    finished: Condvar,
}

impl Shared {
    fn lock(&self) -> MutexGuard<'_, State> {
        // (nothing here panics with the lock held; a poisoned lock's state is still whole)
        self.state.lock().unwrap_or_else(PoisonError::into_inner)
    }
}

/// The temporary files of this process not yet named nor removed, each with the process that
/// made it (a child forked from this one inherits the list, not the files' ownership).
static PENDING: Mutex<BTreeMap<PathBuf, u32>> = Mutex::new(BTreeMap::new());

fn pending() -> MutexGuard<'static, BTreeMap<PathBuf, u32>> {
    // (nothing panics with the lock held; a poisoned list is still whole)
    PENDING.lock().unwrap_or_else(PoisonError::into_inner)
}

// The C library's exit functions (`atexit(3)`): run by `exit`, after the interpreter's
// finalization; not by `_exit` (`os._exit`, whose caller sweeps first: `tapegate.launch`).
// (Not Python's `atexit`: a function registered there, even unregistered, makes
// `tapegate.launch.leave` take the interpreter's slow exit.)
extern "C" {
    fn atexit(function: extern "C" fn()) -> std::os::raw::c_int;
}

/// The sweep at the process's exit registered (once, at the first temporary file).
static AT_EXIT: Once = Once::new();

/// [`sweep_pending`] at the process's exit, unless a thread still holds the list (it is
/// naming a file: the exit does not wait for it).
extern "C" fn sweep_at_exit() {
    let mut list = match PENDING.try_lock() {
        Ok(list) => list,
        Err(TryLockError::Poisoned(poisoned)) => poisoned.into_inner(),
        Err(TryLockError::WouldBlock) => return,
    };
    sweep(&mut list);
}

/// The temporary files of `list` this process made, removed and out of it: how many.
fn sweep(list: &mut BTreeMap<PathBuf, u32>) -> usize {
    let me = std::process::id();
    let mut removed = 0;
    list.retain(|tmp, owner| {
        if *owner != me {
            return true;
        }
        if fs::remove_file(tmp).is_ok() {
            removed += 1;
        }
        false
    });
    removed
}

/// `tmp` named or removed: out of the list.
fn forget(tmp: &Path) {
    pending().remove(tmp);
}

/// `formats.files.joined`: `below` in `folder`, written as pathlib writes it (`folder` as
/// `formats.files.pure` writes it: only `/` and `//` end in a slash, `.` is left out).
fn joined(folder: &OsStr, below: &[u8]) -> PathBuf {
    let folder = folder.as_bytes();
    let mut path = Vec::with_capacity(folder.len() + 1 + below.len());
    if folder != b"." {
        path.extend_from_slice(folder);
        if !folder.ends_with(b"/") {
            path.push(b'/');
        }
    }
    path.extend_from_slice(below);
    PathBuf::from(OsString::from_vec(path))
}

/// A new temporary file in `folder` (as `formats.files.pure` writes it), `.HINT.XXXXXXXX.part`
/// (8 hex digits drawn afresh while the name is taken), created with mode 0666 and the
/// process's umask, and entered in the list of temporary files in the same step: its
/// descriptor (the caller's to close) and its path.
fn make_pending(folder: &OsStr, hint: &OsStr) -> io::Result<(File, PathBuf)> {
    AT_EXIT.call_once(|| {
        // SAFETY: registers a function of this library, which the interpreter never unloads;
        // it only takes the list's lock (without waiting) and removes files. (Refused when
        // the C library's table is full: then only `formats.files.sweep` sweeps.)
        unsafe { atexit(sweep_at_exit) };
    });
    let keys = std::collections::hash_map::RandomState::new();
    let mut draw = 0u64;
    loop {
        // (std's RandomState is seeded from the system's random source once a thread, its
        // keys moved on at each one made: a name no other process draws the same way; O_EXCL
        // makes a name taken anyway only another draw)
        let mut hasher = keys.build_hasher();
        hasher.write_u64(draw);
        hasher.write_u32(std::process::id());
        let number = hasher.finish() as u32;
        draw += 1;
        let mut name = Vec::with_capacity(hint.len() + 16);
        name.push(b'.');
        name.extend_from_slice(hint.as_bytes());
        name.extend_from_slice(format!(".{number:08x}.part").as_bytes());
        let tmp = joined(folder, &name);
        // The list is taken once the file is made, not across its `open`: that waits for the
        // folder's lock while a commit thread renames in it, and the list held meanwhile
        // stopped the other workers' files and the commits' `forget` behind it (a sweep
        // running between the two misses the file as it would miss one made just after it)
        match OpenOptions::new()
            .write(true)
            .create_new(true)
            .mode(0o666)
            .open(&tmp)
        {
            Ok(file) => {
                pending().insert(tmp.clone(), std::process::id());
                return Ok((file, tmp));
            }
            Err(error) if error.kind() == io::ErrorKind::AlreadyExists => continue,
            Err(error) => return Err(error),
        }
    }
}

/// `path` with its name's stem followed by `.N` (`STEM.N.EXT`; the stem and the extension as
/// pathlib reads them: the extension is the name's last `.` and what follows, unless the
/// name begins or ends there).
fn version_name(path: &Path, n: u64) -> PathBuf {
    let whole = path.as_os_str().as_bytes();
    let start = whole.iter().rposition(|&b| b == b'/').map_or(0, |i| i + 1);
    let name = &whole[start..];
    let dot = match name.iter().rposition(|&b| b == b'.') {
        Some(i) if i > 0 && i + 1 < name.len() => i,
        _ => name.len(),
    };
    let mut out = Vec::with_capacity(whole.len() + 8);
    out.extend_from_slice(&whole[..start + dot]);
    out.extend_from_slice(format!(".{n}").as_bytes());
    out.extend_from_slice(&name[dot..]);
    PathBuf::from(OsString::from_vec(out))
}

/// The steps of one commit (the module's list), the temporary file removed if one fails:
/// the path named. With `version` (and not `overwrite`) a name taken is passed over for the
/// next free version name, else it fails with `AlreadyExists`.
fn commit(
    file: File,
    tmp: &Path,
    target: &Path,
    overwrite: bool,
    version: bool,
) -> io::Result<PathBuf> {
    let synced = if overwrite {
        keep_access(&file, target)
    } else {
        Ok(())
    }
    .and_then(|()| file.sync_all()); // fsync(2)
    drop(file);
    let named = synced.and_then(|()| {
        if overwrite {
            return fs::rename(tmp, target).map(|()| target.to_path_buf());
        }
        let mut n = 0;
        loop {
            let name = if n == 0 {
                target.to_path_buf()
            } else {
                version_name(target, n)
            };
            let linked = match fs::hard_link(tmp, &name) {
                Ok(()) => fs::remove_file(tmp),
                Err(error) if no_links(&error) => rename_no_replace(tmp, &name),
                Err(error) => Err(error),
            };
            match linked {
                Ok(()) => return Ok(name),
                Err(error) if version && error.kind() == io::ErrorKind::AlreadyExists => n += 1,
                Err(error) => return Err(error),
            }
        }
    });
    if named.is_err() {
        let _ = fs::remove_file(tmp); // (gone already where the link and removal were done)
    }
    forget(tmp);
    named
}

// Linux's error numbers the commit tells apart (the same on x86-64 and AArch64)
const EPERM: i32 = 1;
const EINVAL: i32 = 22;
const ENOSYS: i32 = 38;
const EOPNOTSUPP: i32 = 95;

/// Whether a hard link failed because the file system has none: FAT and exFAT, the USB stick
/// a shop carries to the control (Linux's `link(2)` gives EPERM where the file system has no
/// link operation), some network and FUSE file systems (EOPNOTSUPP, ENOSYS). Review 44,
/// finding 6: without a way round it, every output not replacing a file failed there.
fn no_links(error: &io::Error) -> bool {
    matches!(error.raw_os_error(), Some(EPERM | ENOSYS | EOPNOTSUPP))
}

/// `tmp` renamed to `name` where no file has that name, else `AlreadyExists`, on a file
/// system without hard links ([`no_links`]): `renameat2(RENAME_NOREPLACE)` (Linux 3.15; FAT
/// and exFAT take it), the kernel's own test and rename in one step, called by its system
/// call number, as a C library older than 2.28 has no `renameat2`; where the kernel or the
/// file system does not offer it (EINVAL, ENOSYS), a look at the name and then a rename: a
/// file made under that name between the two is replaced (the one window left, on such a
/// file system only).
fn rename_no_replace(tmp: &Path, name: &Path) -> io::Result<()> {
    #[cfg(all(
        target_os = "linux",
        any(target_arch = "x86_64", target_arch = "aarch64")
    ))]
    {
        use std::ffi::CString;
        use std::os::raw::{c_int, c_long, c_uint};
        use std::os::unix::ffi::OsStrExt;

        extern "C" {
            fn syscall(number: c_long, ...) -> c_long;
        }
        #[cfg(target_arch = "x86_64")]
        const SYS_RENAMEAT2: c_long = 316;
        #[cfg(target_arch = "aarch64")]
        const SYS_RENAMEAT2: c_long = 276;
        const AT_FDCWD: c_int = -100;
        const RENAME_NOREPLACE: c_uint = 1;
        let from = CString::new(tmp.as_os_str().as_bytes())?;
        let to = CString::new(name.as_os_str().as_bytes())?;
        // SAFETY: two NUL-terminated paths that live across the call, and plain integers, as
        // renameat2(2) takes them
        let done = unsafe {
            syscall(
                SYS_RENAMEAT2,
                AT_FDCWD,
                from.as_ptr(),
                AT_FDCWD,
                to.as_ptr(),
                RENAME_NOREPLACE,
            )
        };
        if done == 0 {
            return Ok(());
        }
        let error = io::Error::last_os_error();
        if !matches!(error.raw_os_error(), Some(EINVAL | ENOSYS)) {
            return Err(error);
        }
    }
    if fs::symlink_metadata(name).is_ok() {
        return Err(io::Error::new(
            io::ErrorKind::AlreadyExists,
            format!("{} exists", name.display()),
        ));
    }
    fs::rename(tmp, name)
}

/// A replaced file's access given to the file that replaces it (`install -p`, an editor's
/// save): where `target` is a regular file (not followed: a symbolic link there is replaced by
/// the new file, as before, and a device or a FIFO never reaches a commit), the new file takes
/// its owner and group where the system allows it (`fchown`: as root; else the group alone,
/// where the user is one of its members; a refusal (EPERM) leaves the process's own) and then
/// its permission bits (`fchmod`, after the `fchown` that may clear set-user-ID bits; only
/// the 0777 bits: a set-user-ID or sticky bit is not carried over), never wider than the old
/// file's: where the group is not kept, the new group's bits are no more than the others'
/// (review 47, F2; the old owner, where not kept, reads the file as others may). Without it
/// `--force` made a 0640 program 0644 and the runner's (review 42, finding 5). A target that
/// is not there (gone meanwhile), or not a regular file, leaves the new file as it was made
/// (0666 and the umask). A failing `fchmod` fails the commit (the new file is never left
/// wider than the one it replaces), but on a file system that keeps no modes (ENOSYS,
/// EOPNOTSUPP).
fn keep_access(file: &File, target: &Path) -> io::Result<()> {
    use std::os::unix::fs::{MetadataExt, PermissionsExt};

    let old = match fs::symlink_metadata(target) {
        Ok(old) if old.file_type().is_file() => old,
        _ => return Ok(()),
    };
    let made = file.metadata()?;
    if (made.uid(), made.gid()) != (old.uid(), old.gid()) {
        let owned = std::os::unix::fs::fchown(file, Some(old.uid()), Some(old.gid()));
        if owned.is_err() && made.gid() != old.gid() {
            // (not root: the owner stays the user's; the group where the user is a member)
            let _ = std::os::unix::fs::fchown(file, None, Some(old.gid()));
        }
    }
    // the old bits, never wider: where the group could not be kept, its members (another
    // group now) have no more than the others had (a 0640 program of group `shop` made by a
    // user outside it is 0600; given 0666 and the umask it was world-readable: review 47,
    // F2); the new owner, who replaced the file, has the old owner's bits
    let now = file.metadata()?;
    let mut mode = old.mode() & 0o777;
    if now.gid() != old.gid() {
        mode = (mode & !0o070) | ((mode >> 3) & mode & 0o007) << 3;
    }
    match file.set_permissions(fs::Permissions::from_mode(mode)) {
        // a file system that keeps no modes (a FUSE mount without them: ENOSYS, EOPNOTSUPP)
        // has none to widen; --force failed there on every file (review 45, finding L6)
        Err(error) if matches!(error.raw_os_error(), Some(ENOSYS | EOPNOTSUPP)) => Ok(()),
        set => set,
    }
}

/// A commit of the pool's.
fn commit_job(job: Job) -> io::Result<()> {
    commit(job.file, &job.tmp, &job.target, job.overwrite, false).map(drop)
}

/// `PendingFile`'s temporary file: `(descriptor, path)` of a new hidden file in `folder` (see
/// [`make_pending`]), the descriptor the caller's. The `OSError` of the folder where it cannot
/// be made.
#[pyfunction]
pub(crate) fn pending_file(
    py: Python<'_>,
    folder: OsString,
    hint: OsString,
) -> PyResult<(RawFd, OsString)> {
    match py.allow_threads(|| make_pending(&folder, &hint)) {
        Ok((file, tmp)) => Ok((file.into_raw_fd(), tmp.into_os_string())),
        Err(error) => Err(os_error(py, error)),
    }
}

/// The temporary file's descriptor the caller hands over (one of its own, which nothing else
/// closes: PendingFile's, or `hand_over`'s duplicate), owned by the File from here on: the
/// one commit and the batch's commit threads take it alike.
fn handed_over(fd: RawFd) -> PyResult<File> {
    if fd < 0 {
        return Err(PyValueError::new_err("a file descriptor is not negative"));
    }
    // SAFETY: a descriptor of the caller's own that nothing else closes (above).
    Ok(unsafe { File::from_raw_fd(fd) })
}

/// One file's commit ([`commit`]) on the caller's thread, the GIL released: the data written
/// to the open file `fd` (handed over: closed here, whatever happens) at `tmp` named `target`
/// (replacing a file there when `overwrite`; else a name taken is passed over for the next
/// version name with `version`, or refused with `FileExistsError`). The path named, or the
/// `OSError` of the step that failed (the temporary file removed).
#[pyfunction]
pub(crate) fn commit_file(
    py: Python<'_>,
    fd: RawFd,
    tmp: PathBuf,
    target: PathBuf,
    overwrite: bool,
    version: bool,
) -> PyResult<OsString> {
    let file = handed_over(fd)?;
    match py.allow_threads(|| commit(file, &tmp, &target, overwrite, version)) {
        Ok(named) => Ok(named.into_os_string()),
        Err(error) => Err(os_error(py, error)),
    }
}

/// The temporary file `tmp` removed (if it is there) and out of the list.
#[pyfunction]
pub(crate) fn discard_file(py: Python<'_>, tmp: PathBuf) -> PyResult<()> {
    match fs::remove_file(&tmp) {
        Err(error) if error.kind() != io::ErrorKind::NotFound => Err(os_error(py, error)),
        _ => {
            forget(&tmp);
            Ok(())
        }
    }
}

/// Every temporary file this process made and has not named nor removed, removed: how many.
/// For the process's end (a ^C between a file's making and its commit, in any thread), when
/// nothing will name them: run by the C library's `exit` ([`sweep_at_exit`]), and called by
/// `formats.files.sweep` where the process ends by `os._exit`.
#[pyfunction]
pub(crate) fn sweep_pending() -> usize {
    sweep(&mut pending())
}

/// A thread of the pool: the jobs in the order they were handed over, until it is closed and
/// none is left. A waiter is notified once the lock is let go: notified with it held, a
/// woken thread ran only to wait for the lock, and the notifier was put off its core to let
/// it (`queue` likewise).
fn serve(shared: Arc<Shared>) {
    let mut state = shared.lock();
    loop {
        if let Some(job) = state.queue.pop_front() {
            drop(state);
            let ticket = job.ticket;
            let outcome = commit_job(job);
            shared.lock().done.insert(ticket, outcome);
            shared.finished.notify_all();
            state = shared.lock();
        } else if state.closed {
            return;
        } else {
            state.idle += 1;
            state = shared
                .work
                .wait(state)
                .unwrap_or_else(PoisonError::into_inner);
            state.idle -= 1;
        }
    }
}

/// The commits of a batch's outputs, run by up to `threads` threads of their own, started as
/// the commits come, in the order they are handed over.
#[pyclass(frozen, module = "formats._core")]
pub(crate) struct Commits {
    shared: Arc<Shared>,
    limit: usize,
    handles: Mutex<Vec<JoinHandle<()>>>,
}

#[pymethods]
impl Commits {
    #[new]
    fn new(threads: usize) -> PyResult<Self> {
        if threads == 0 {
            return Err(PyValueError::new_err("Commits needs one thread at least"));
        }
        Ok(Commits {
            shared: Arc::default(),
            limit: threads,
            handles: Mutex::default(),
        })
    }

    /// The output whose data was written to the open file `fd` (a descriptor handed over:
    /// closed here, whatever happens) at `tmp`, to be named `target` (replacing a file there
    /// when `overwrite`, else refused with `FileExistsError`): its ticket, for `done` and
    /// `wait`. Once the pool is closed the commit is run here, with the GIL released.
    fn submit(
        &self,
        py: Python<'_>,
        fd: RawFd,
        tmp: PathBuf,
        target: PathBuf,
        overwrite: bool,
    ) -> PyResult<u64> {
        let file = handed_over(fd)?;
        // The GIL released: a thread woken here (or started) may take this thread's core at
        // once, its fsync's work in the kernel, and the other workers must not wait for the
        // GIL meanwhile (held here, it made one hand-over 1.6 ms in a profile).
        let ticket = py.allow_threads(|| self.queue(file, tmp, target, overwrite));
        Ok(ticket)
    }

    /// Whether the commit of `ticket` is done (and not yet waited for).
    fn done(&self, ticket: u64) -> bool {
        self.shared.lock().done.contains_key(&ticket)
    }

    /// Waits (the GIL released) for the commit of `ticket`: None once the output has its name,
    /// else the `OSError` of the step that failed (its temporary file removed). A ticket is
    /// waited for once.
    fn wait(&self, py: Python<'_>, ticket: u64) -> PyResult<()> {
        let outcome = py.allow_threads(|| {
            let mut state = self.shared.lock();
            if !state.open.contains(&ticket) {
                return None;
            }
            loop {
                if let Some(outcome) = state.done.remove(&ticket) {
                    state.open.remove(&ticket);
                    return Some(outcome);
                }
                state = self
                    .shared
                    .finished
                    .wait(state)
                    .unwrap_or_else(PoisonError::into_inner);
            }
        });
        match outcome {
            None => Err(PyValueError::new_err(format!(
                "no commit to wait for has the ticket {ticket}"
            ))),
            Some(Ok(())) => Ok(()),
            Some(Err(error)) => Err(os_error(py, error)),
        }
    }

    /// Every commit handed over run, the threads ended (the GIL released meanwhile); a commit
    /// handed over after this is run by `submit` itself.
    fn close(&self, py: Python<'_>) {
        {
            let mut state = self.shared.lock();
            state.closed = true;
            self.shared.work.notify_all();
        }
        let handles =
            std::mem::take(&mut *self.handles.lock().unwrap_or_else(PoisonError::into_inner));
        py.allow_threads(|| {
            for handle in handles {
                let _ = handle.join();
            }
        });
    }
}

impl Commits {
    /// `submit`'s work, without the GIL: the job queued for a thread (woken, or started), or
    /// run here once the pool is closed or where no thread could be started.
    fn queue(&self, file: File, tmp: PathBuf, target: PathBuf, overwrite: bool) -> u64 {
        let mut state = self.shared.lock();
        let ticket = state.next;
        state.next += 1;
        state.open.insert(ticket);
        let job = Job {
            ticket,
            file,
            tmp,
            target,
            overwrite,
        };
        if state.closed {
            drop(state);
            return self.run_here(job);
        }
        state.queue.push_back(job);
        if state.idle > 0 {
            drop(state); // (notified once the lock is let go: `serve`)
            self.shared.work.notify_one();
        } else if state.threads < self.limit {
            let shared = Arc::clone(&self.shared);
            let spawned = std::thread::Builder::new()
                .name("tapegate-commit".into())
                .spawn(move || serve(shared));
            match spawned {
                Ok(handle) => {
                    state.threads += 1;
                    self.handles
                        .lock()
                        .unwrap_or_else(PoisonError::into_inner)
                        .push(handle);
                }
                Err(_) if state.threads == 0 => {
                    // no thread to run it (the system refused one): run here, as after close
                    let job = state.queue.pop_back().expect("pushed above");
                    drop(state);
                    return self.run_here(job);
                }
                Err(_) => {} // (the threads there take it)
            }
        }
        ticket
    }

    /// A commit run by the caller's thread.
    fn run_here(&self, job: Job) -> u64 {
        let ticket = job.ticket;
        let outcome = commit_job(job);
        self.shared.lock().done.insert(ticket, outcome);
        ticket
    }
}

impl Drop for Commits {
    /// Not closed (an object dropped without `close`): the threads end once the jobs queued
    /// are done, not waited for.
    fn drop(&mut self) {
        self.shared.lock().closed = true;
        self.shared.work.notify_all();
    }
}
