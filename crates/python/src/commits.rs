//! The fsync and naming of a batch's outputs (`tapegate convert` of several files), done by
//! threads of the core that never take the GIL: `formats.files.PendingFile.commit`'s steps for
//! an output that is a regular file, each output's in one native step.
//!
//! Why here: the batch ran them in Python threads (`tapegate.converting.Commits`), each output's
//! commit an fsync, a close, a stat and a rename or a link, each a system call that dropped
//! and took back the GIL, in threads woken by the disk's completions while the converting
//! threads wanted the GIL for their own files (docs/benchmarks.md, "the commits without the
//! GIL"). A commit here takes the GIL once, to be handed over (`submit`), and once to be
//! waited for (`wait`); what it does meanwhile is the same, in the same order:
//!
//! 1. the temporary file's data fsync'd (its descriptor, handed over: closed after);
//! 2. its name given: a rename over the target when it may be replaced, else a hard link that
//!    fails if the name is taken (a file that appeared meanwhile is never replaced), then the
//!    temporary name removed;
//! 3. on any failure, the temporary file removed: nothing is left but what was there before.
//!
//! The folder's fsync (the names on disk) stays the batch's, once per folder at its end, and a
//! target that is not a regular file (a device, a FIFO) is written into by Python, never here.

use std::collections::{HashMap, HashSet, VecDeque};
use std::fs::{self, File};
use std::io;
use std::os::fd::{FromRawFd, RawFd};
use std::path::PathBuf;
use std::sync::{Arc, Condvar, Mutex, MutexGuard, PoisonError};
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

/// The steps of one commit (the module's list), the temporary file removed if one fails.
fn commit(job: Job) -> io::Result<()> {
    let Job {
        file,
        tmp,
        target,
        overwrite,
        ..
    } = job;
    let synced = file.sync_all(); // fsync(2)
    drop(file);
    let named = synced.and_then(|()| {
        if overwrite {
            fs::rename(&tmp, &target)
        } else {
            fs::hard_link(&tmp, &target).and_then(|()| fs::remove_file(&tmp))
        }
    });
    if named.is_err() {
        let _ = fs::remove_file(&tmp); // (gone already where the link and removal were done)
    }
    named
}

/// A thread of the pool: the jobs in the order they were handed over, until it is closed and
/// none is left.
fn serve(shared: Arc<Shared>) {
    let mut state = shared.lock();
    loop {
        if let Some(job) = state.queue.pop_front() {
            drop(state);
            let ticket = job.ticket;
            let outcome = commit(job);
            state = shared.lock();
            state.done.insert(ticket, outcome);
            shared.finished.notify_all();
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
        if fd < 0 {
            return Err(PyValueError::new_err("a file descriptor is not negative"));
        }
        // SAFETY: the caller hands over a descriptor of its own (PendingFile.hand_over's
        // duplicate), which nothing else closes: owned by this File from here on.
        let file = unsafe { File::from_raw_fd(fd) };
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
        let outcome = commit(job);
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
