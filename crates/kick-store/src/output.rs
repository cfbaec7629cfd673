//! Whole-or-nothing output files: every result file, figure and report page
//! of the workspace is written through [`Staged`] (or [`write`]).
//!
//! - The content goes to a temporary file beside the target, named for this
//!   process (`NAME.<pid>-<n>.tmp.EXT`, the extension kept for writers that
//!   pick a format from it), and is renamed onto the target when complete:
//!   the target is always one whole run, the old one or the new one.
//! - One writer per target: an advisory lock on `NAME.EXT.lock` is held from
//!   [`Staged::begin`] to the end, and a second writer, in this process or
//!   another, is refused naming the file and the holder. The lock file is
//!   removed when the writer ends; one left by a killed process holds no lock
//!   and is taken over.
//! - Temporary files left by a killed writer of the same target are removed
//!   once the lock is held (no live writer can own them then).
//! - A target that already holds the content is left as it was, bytes and
//!   time stamps ([`Staged::commit_unless`]; by bytes, or for HDF5 result
//!   files by content without the checkout's provenance): a rerun that
//!   changes no number rewrites no file.
//! - [`install_signal_cleanup`] makes SIGINT, SIGTERM and SIGHUP remove this
//!   process's temporary and lock files before it exits (130, 143, 129).

use std::fs::{File, OpenOptions, TryLockError};
use std::io::{Read, Seek, SeekFrom, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Mutex, MutexGuard};

#[derive(Debug, thiserror::Error)]
pub enum OutputError {
    #[error(
        "{}: another process{} is writing this file now (lock {}); wait for it to end or write elsewhere",
        path.display(),
        holder.map(|p| format!(" (pid {p})")).unwrap_or_default(),
        lock.display()
    )]
    Busy { path: PathBuf, lock: PathBuf, holder: Option<u32> },
    #[error("cannot write {}: {message}", path.display())]
    Io { path: PathBuf, message: String },
    #[error("`{flag}` = `{}`: {message}", path.display())]
    Refused { flag: String, path: PathBuf, message: String },
}

fn io(path: &Path) -> impl Fn(std::io::Error) -> OutputError + '_ {
    move |e| OutputError::Io { path: path.to_path_buf(), message: e.to_string() }
}

/// Files to remove if a signal ends the process: temporary and lock files.
static PENDING: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

fn pending() -> MutexGuard<'static, Vec<PathBuf>> {
    // A panic elsewhere must not keep the cleanup from running.
    PENDING.lock().unwrap_or_else(|e| e.into_inner())
}

fn register(path: &Path) {
    pending().push(path.to_path_buf());
}

fn unregister(list: &mut Vec<PathBuf>, path: &Path) {
    if let Some(i) = list.iter().rposition(|p| p == path) {
        list.swap_remove(i);
    }
}

/// On SIGINT, SIGTERM or SIGHUP: remove this process's temporary and lock
/// files and exit with 128 + the signal (130, 143, 129). Call once, early, in
/// a program (not a library host with signal handling of its own); later
/// calls do nothing. The work runs on a thread of its own, not in the
/// handler; the exit skips atexit handlers, which could meet HDF5 mid-call.
pub fn install_signal_cleanup() -> Result<(), OutputError> {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
    static INSTALLED: Mutex<bool> = Mutex::new(false);
    let mut installed = INSTALLED.lock().unwrap_or_else(|e| e.into_inner());
    if *installed {
        return Ok(());
    }
    let mut signals = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP])
        .map_err(|e| OutputError::Io { path: PathBuf::from("(signal handler)"), message: e.to_string() })?;
    std::thread::Builder::new()
        .name("kick-signals".into())
        .spawn(move || {
            if let Some(signal) = signals.forever().next() {
                // Held to the exit: a commit in progress finishes first or not at all.
                let list = pending();
                for path in list.iter() {
                    let _ = std::fs::remove_file(path);
                }
                signal_hook::low_level::exit(128 + signal);
            }
        })
        .map_err(|e| OutputError::Io { path: PathBuf::from("(signal thread)"), message: e.to_string() })?;
    *installed = true;
    Ok(())
}

/// Refuse, before any work, an output `out` (given as `flag`) that does not
/// end in `.EXT`, is a directory, or names one of `inputs` ([`check_paths`]).
pub fn check_output(out: &Path, flag: &str, ext: &str, inputs: &[&Path]) -> Result<(), OutputError> {
    if out.extension().and_then(|e| e.to_str()) != Some(ext) {
        return Err(OutputError::Refused {
            flag: flag.to_string(),
            path: out.to_path_buf(),
            message: format!("an output file must end in `.{ext}` (this keeps an input from being replaced by mistake)"),
        });
    }
    check_paths(&[Target::File { flag, path: out }], inputs)
}

/// A path a command writes, with the flag (or key) that named it.
#[derive(Debug, Clone, Copy)]
pub enum Target<'a> {
    /// One file.
    File { flag: &'a str, path: &'a Path },
    /// A folder the command owns: any file below it may be written (results
    /// and figures of `kick reproduce`).
    Folder { flag: &'a str, path: &'a Path },
}

/// The one check of every command that writes, made before any work: no
/// file it writes is a file it reads, and no folder it writes into holds
/// one. Paths are compared as they will resolve when written
/// ([`resolve`]: `nodir/../a.h5` is `a.h5` once the writer has created
/// `nodir`), and files also by device and inode (a second name or a hard
/// link to an input counts). A file target that is a directory is refused too.
pub fn check_paths(writes: &[Target], reads: &[&Path]) -> Result<(), OutputError> {
    let reads: Vec<(&Path, PathBuf)> = reads.iter().map(|&r| (r, resolve(r))).collect();
    for target in writes {
        let (&Target::File { flag, path } | &Target::Folder { flag, path }) = target;
        let refused = |message: String| OutputError::Refused { flag: flag.to_string(), path: path.to_path_buf(), message };
        let resolved = resolve(path);
        // Said when the path reads as something else than it will be.
        let meaning = |input: &Path| {
            let plain = input.is_absolute() == path.is_absolute() && input.components().eq(path.components());
            if plain {
                String::new()
            } else {
                format!(" (it resolves to {})", resolved.display())
            }
        };
        match target {
            Target::Folder { .. } if resolved.exists() && !resolved.is_dir() => {
                return Err(refused("it is a file, not a folder; give a folder".into()));
            }
            Target::File { .. } if resolved.is_dir() => return Err(refused("it is a directory; give a file name".into())),
            _ => {}
        }
        // The folder the writer will make files in: refused now, by the flag, not after the work.
        let folder = match target {
            Target::File { .. } => resolved.parent().map(Path::to_path_buf).unwrap_or_default(),
            Target::Folder { .. } => resolved.clone(),
        };
        writable_folder(&folder).map_err(refused)?;
        match target {
            Target::File { .. } => {
                for (input, real) in &reads {
                    if *real == resolved || is_same_file(&resolved, real) {
                        return Err(refused(format!("is the input {}{}; write elsewhere", input.display(), meaning(input))));
                    }
                }
            }
            Target::Folder { .. } => {
                for (input, real) in &reads {
                    if real.starts_with(&resolved) {
                        return Err(refused(format!(
                            "holds the input {}{}, and this folder's files are written; give a folder of its own",
                            input.display(),
                            meaning(input)
                        )));
                    }
                }
            }
        }
    }
    Ok(())
}

/// Why `directory` could not be made: an existing part of it that is a
/// file, not a folder, is named (the system says only "File exists").
fn folder_failure(directory: &Path, e: &std::io::Error) -> String {
    let file = directory.ancestors().find(|a| std::fs::metadata(a).is_ok_and(|m| !m.is_dir()));
    match file {
        Some(f) => format!("{} is a file, not a folder", f.display()),
        None => format!("cannot make its folder {}: {e}", directory.display()),
    }
}

/// Whether files can be made in the nearest existing folder of `path`
/// (itself, if it is one): a probe file made and removed there. Permission
/// bits do not say it (root passes them; /sys and /proc refuse root too).
fn writable_folder(path: &Path) -> Result<(), String> {
    let Some(folder) = path.ancestors().find(|a| a.is_dir()) else { return Ok(()) };
    if let Some(file) = path.ancestors().take_while(|a| *a != folder).find(|a| a.exists()) {
        return Err(format!("{} is a file, not a folder", file.display()));
    }
    let probe = folder.join(format!(".kick-write-probe.{}", std::process::id()));
    let mut options = OpenOptions::new();
    options.write(true).create_new(true);
    no_follow(&mut options);
    match options.open(&probe) {
        Ok(_) => {
            let _ = std::fs::remove_file(&probe);
            Ok(())
        }
        Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => Ok(()),
        Err(e) => Err(format!("files cannot be made in {}: {e}", folder.display())),
    }
}

/// What `path` will name once the directories a writer creates exist: its
/// longest existing prefix resolved by the file system (links followed),
/// the rest lexically, where `x/..` cancels because `x` will then be a
/// directory (so `nodir/../a.h5` is `./a.h5`, though `nodir` does not
/// exist yet). Absolute.
pub fn resolve(path: &Path) -> PathBuf {
    use std::path::Component;
    let absolute = if path.is_absolute() { path.to_path_buf() } else { std::env::current_dir().unwrap_or_default().join(path) };
    // `base` exists and is canonical; `tail` does not exist yet.
    let mut base = PathBuf::new();
    let mut tail: Vec<&std::ffi::OsStr> = Vec::new();
    for component in absolute.components() {
        match component {
            Component::Prefix(_) | Component::RootDir => base.push(component.as_os_str()),
            Component::CurDir => {}
            Component::ParentDir => {
                if tail.pop().is_none() {
                    // The parent of a canonical path is its lexical parent.
                    base.pop();
                }
            }
            Component::Normal(name) => match std::fs::canonicalize(base.join(name)) {
                Ok(real) if tail.is_empty() => base = real,
                _ => tail.push(name),
            },
        }
    }
    base.extend(tail);
    base
}

/// Whether two paths name one existing file.
#[cfg(unix)]
pub fn is_same_file(a: &Path, b: &Path) -> bool {
    use std::os::unix::fs::MetadataExt;
    match (std::fs::metadata(a), std::fs::metadata(b)) {
        (Ok(a), Ok(b)) => a.dev() == b.dev() && a.ino() == b.ino(),
        _ => false,
    }
}

#[cfg(not(unix))]
pub fn is_same_file(a: &Path, b: &Path) -> bool {
    matches!((a.canonicalize(), b.canonicalize()), (Ok(a), Ok(b)) if a == b)
}

/// `NAME.EXT.lock` beside `target`.
pub fn lock_path(target: &Path) -> PathBuf {
    let mut name = target.file_name().unwrap_or_default().to_owned();
    name.push(".lock");
    target.with_file_name(name)
}

/// (stem, ".EXT" or "") of the target's file name.
fn split_name(target: &Path) -> (String, String) {
    let stem = target.file_stem().unwrap_or_default().to_string_lossy().into_owned();
    let ext = target.extension().map(|e| format!(".{}", e.to_string_lossy())).unwrap_or_default();
    (stem, ext)
}

/// Whether `name` is a temporary file of a target with this stem and extension.
fn is_temporary_of(name: &str, stem: &str, ext: &str) -> bool {
    let Some(middle) = name.strip_prefix(stem).and_then(|r| r.strip_prefix('.')).and_then(|r| r.strip_suffix(ext)) else {
        return false;
    };
    let Some(ids) = middle.strip_suffix(".tmp") else {
        return false;
    };
    let mut parts = ids.split('-');
    let numeric = |p: Option<&str>| p.is_some_and(|p| !p.is_empty() && p.bytes().all(|b| b.is_ascii_digit()));
    numeric(parts.next()) && numeric(parts.next()) && parts.next().is_none()
}

/// A held lock on a target: the lock file exists and is locked by us.
struct Lock {
    path: PathBuf,
    _file: File,
}

impl Lock {
    fn acquire(target: &Path) -> Result<Lock, OutputError> {
        let path = lock_path(target);
        // A few tries: the holder may remove its lock file between our open
        // and our lock, leaving us a lock on a file no longer there.
        for _ in 0..100 {
            let mut file = open_lock_file(&path)?;
            match file.try_lock() {
                Ok(()) => {}
                Err(TryLockError::WouldBlock) => {
                    let mut text = String::new();
                    let _ = file.read_to_string(&mut text);
                    return Err(OutputError::Busy { path: target.to_path_buf(), lock: path, holder: text.trim().parse().ok() });
                }
                Err(TryLockError::Error(e)) => return Err(io(&path)(e)),
            }
            if !same_file(&file, &path) {
                continue;
            }
            // Registered before anything else can fail, so a signal removes it.
            register(&path);
            let lock = Lock { path, _file: file };
            let mut file = &lock._file;
            file.set_len(0)
                .and_then(|()| file.seek(SeekFrom::Start(0)))
                .and_then(|_| write!(file, "{}", std::process::id()))
                .map_err(io(&lock.path))?;
            return Ok(lock);
        }
        Err(OutputError::Io { path, message: "the lock file keeps being replaced".into() })
    }
}

/// The lock file, created exclusively or (left by a killed writer) opened
/// without following a link: a planted link, FIFO, directory or hard link to
/// another file is refused, never written through (another user of a shared
/// directory could otherwise make us clobber any file we may write).
fn open_lock_file(path: &Path) -> Result<File, OutputError> {
    let refused = |what: &str| OutputError::Io {
        path: path.to_path_buf(),
        message: format!("the lock file is {what}, not a regular file of its own; remove it if no kick is writing here"),
    };
    let mut options = OpenOptions::new();
    options.read(true).write(true);
    no_follow(&mut options);
    match options.clone().create_new(true).open(path) {
        Ok(file) => return Ok(file),
        Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => {}
        Err(e) => return Err(io(path)(e)),
    }
    let kind = std::fs::symlink_metadata(path).map_err(io(path))?.file_type();
    if kind.is_symlink() {
        return Err(refused("a symbolic link"));
    }
    if !kind.is_file() {
        return Err(refused("a directory or special file"));
    }
    let file =
        options.open(path).map_err(|e| if e.raw_os_error() == Some(libc::ELOOP) { refused("a symbolic link") } else { io(path)(e) })?;
    let metadata = file.metadata().map_err(io(path))?;
    if !metadata.is_file() {
        return Err(refused("a directory or special file"));
    }
    if links(&metadata) != 1 {
        return Err(refused("a hard link to another file"));
    }
    Ok(file)
}

#[cfg(unix)]
fn no_follow(options: &mut OpenOptions) {
    use std::os::unix::fs::OpenOptionsExt;
    // Non-blocking too: a FIFO planted between the checks must not hang us.
    options.custom_flags(libc::O_NOFOLLOW | libc::O_NONBLOCK);
}

#[cfg(not(unix))]
fn no_follow(_options: &mut OpenOptions) {}

#[cfg(unix)]
fn links(metadata: &std::fs::Metadata) -> u64 {
    std::os::unix::fs::MetadataExt::nlink(metadata)
}

#[cfg(not(unix))]
fn links(_metadata: &std::fs::Metadata) -> u64 {
    1
}

impl Drop for Lock {
    fn drop(&mut self) {
        // Removed while still locked, then unlocked when the file closes.
        let mut list = pending();
        let _ = std::fs::remove_file(&self.path);
        unregister(&mut list, &self.path);
    }
}

#[cfg(unix)]
fn same_file(file: &File, path: &Path) -> bool {
    use std::os::unix::fs::MetadataExt;
    match (file.metadata(), std::fs::metadata(path)) {
        (Ok(a), Ok(b)) => a.dev() == b.dev() && a.ino() == b.ino(),
        _ => false,
    }
}

#[cfg(not(unix))]
fn same_file(_file: &File, path: &Path) -> bool {
    path.exists()
}

/// A fresh name of this process beside `target`: `NAME.<pid>-<n>.tmp.EXT`
/// (what [`remove_stale_temporaries`] takes over once its writer is gone).
fn temporary_name(target: &Path, stem: &str, ext: &str) -> PathBuf {
    static SEQUENCE: AtomicU64 = AtomicU64::new(0);
    let n = SEQUENCE.fetch_add(1, Ordering::Relaxed);
    target.with_file_name(format!("{stem}.{}-{n}.tmp{ext}", std::process::id()))
}

/// A file being written: write [`Staged::temporary`], then [`Staged::commit`].
/// Dropped without a commit, the temporary file is removed and the target
/// left as it was.
pub struct Staged {
    target: PathBuf,
    temporary: PathBuf,
    committed: bool,
    // Dropped last: the lock outlives the temporary file.
    _lock: Lock,
}

impl Staged {
    /// Take the target's lock (creating its directory) and name a fresh
    /// temporary file beside it; refused if another writer holds the lock.
    pub fn begin(target: &Path) -> Result<Staged, OutputError> {
        // A link is written through to the file it names (it used to be
        // replaced by a regular file); a link to something else than a
        // regular file (/dev/full, a FIFO) is refused, never renamed over.
        let linked;
        let target = if std::fs::symlink_metadata(target).is_ok_and(|m| m.file_type().is_symlink()) {
            linked = resolve(target);
            if std::fs::metadata(&linked).is_ok_and(|m| !m.is_file()) {
                return Err(OutputError::Io {
                    path: target.to_path_buf(),
                    message: format!("it is a link to {}, not to a regular file; give a file name", linked.display()),
                });
            }
            linked.as_path()
        } else {
            target
        };
        let directory = match target.parent() {
            Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
            _ => PathBuf::from("."),
        };
        std::fs::create_dir_all(&directory)
            .map_err(|e| OutputError::Io { path: target.to_path_buf(), message: folder_failure(&directory, &e) })?;
        // Checked now, not found at the rename after all the work.
        if std::fs::symlink_metadata(target).is_ok_and(|m| m.is_dir()) {
            return Err(OutputError::Io {
                path: target.to_path_buf(),
                message: "it is a directory; give a file name or another directory".into(),
            });
        }
        // A lock that cannot be made is the target's directory refusing it: said of the target.
        let lock = Lock::acquire(target).map_err(|e| match e {
            OutputError::Io { path, message } if path == lock_path(target) => {
                OutputError::Io { path: target.to_path_buf(), message: format!("{message} (making its lock file {})", path.display()) }
            }
            other => other,
        })?;
        let (stem, ext) = split_name(target);
        remove_stale_temporaries(&directory, &stem, &ext);
        // Created here, exclusively and not through a link: the writers that
        // follow (HDF5, plotters) then truncate our own regular file. A name
        // taken by something planted is skipped, never written through.
        let mut options = OpenOptions::new();
        options.write(true).create_new(true);
        no_follow(&mut options);
        for _ in 0..100 {
            let temporary = temporary_name(target, &stem, &ext);
            match options.open(&temporary) {
                Ok(_) => {
                    register(&temporary);
                    return Ok(Staged { target: target.to_path_buf(), temporary, committed: false, _lock: lock });
                }
                Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => continue,
                Err(e) => return Err(io(&temporary)(e)),
            }
        }
        Err(OutputError::Io { path: target.to_path_buf(), message: "every temporary name beside it is taken".into() })
    }

    /// Where to write the content.
    pub fn temporary(&self) -> &Path {
        &self.temporary
    }

    /// The file this becomes.
    pub fn target(&self) -> &Path {
        &self.target
    }

    /// Flush the temporary file to disk and rename it onto the target,
    /// unless the target already holds the same bytes ([`same_bytes`]): then
    /// it is left as it was and the temporary file removed.
    pub fn commit(self) -> Result<PathBuf, OutputError> {
        self.commit_unless(same_bytes)
    }

    /// [`Staged::commit`], unless `same(target, temporary)` says the target
    /// (an existing regular file) already holds this content: then the
    /// target is left as it was, its bytes and time stamps, and the
    /// temporary file removed. A rerun that changes nothing rewrites nothing
    /// (HDF5 result files pass [`crate::compare::same_content`], which leaves
    /// out the provenance of the checkout).
    pub fn commit_unless(mut self, same: impl FnOnce(&Path, &Path) -> bool) -> Result<PathBuf, OutputError> {
        if self.target_holds(same) {
            return Ok(self.target.clone());
        }
        File::open(&self.temporary).and_then(|f| f.sync_all()).map_err(io(&self.temporary))?;
        {
            // Under the registry's lock: a signal sees the rename done or not begun.
            let mut list = pending();
            std::fs::rename(&self.temporary, &self.target).map_err(io(&self.target))?;
            unregister(&mut list, &self.temporary);
            self.committed = true;
        }
        // The rename itself made durable (best effort: not every system opens directories).
        if let Some(dir) = self.target.parent().filter(|d| !d.as_os_str().is_empty()) {
            let _ = File::open(dir).and_then(|d| d.sync_all());
        }
        Ok(self.target.clone())
    }
}

impl Staged {
    /// True when the target is a file that already holds what was written
    /// (`same` compares the two): a clean rerun leaves it as it was.
    fn target_holds(&self, same: impl FnOnce(&Path, &Path) -> bool) -> bool {
        std::fs::symlink_metadata(&self.target).is_ok_and(|m| m.is_file()) && same(&self.target, &self.temporary)
    }
}

impl Drop for Staged {
    fn drop(&mut self) {
        if !self.committed {
            let mut list = pending();
            let _ = std::fs::remove_file(&self.temporary);
            unregister(&mut list, &self.temporary);
        }
    }
}

/// Commit files that belong together (a fit specification and its data, a
/// figure's PNG and SVG) as one: every target gets its new content, or every
/// target keeps what it had. Every temporary file is flushed first, so a
/// full disk stops the set before any rename; the targets' old contents are
/// kept under temporary names until every rename is done and put back if
/// one fails. A signal sees all the renames or none (they run under the
/// registry's lock); only a SIGKILL between them could split the set.
pub fn commit_all(mut files: Vec<Staged>) -> Result<Vec<PathBuf>, OutputError> {
    let targets: Vec<PathBuf> = files.iter().map(|s| s.target.clone()).collect();
    // A target that already holds its new bytes is left as it was (a clean rerun; the dropped temporary goes).
    files.retain(|s| !s.target_holds(same_bytes));
    for s in &files {
        File::open(&s.temporary).and_then(|f| f.sync_all()).map_err(io(&s.target))?;
    }
    let mut list = pending();
    let mut backups: Vec<Option<PathBuf>> = Vec::with_capacity(files.len());
    let restore = |backups: &mut Vec<Option<PathBuf>>, list: &mut Vec<PathBuf>, renamed: &[Staged]| {
        for (s, backup) in renamed.iter().zip(backups.iter()) {
            let _ = match backup {
                Some(old) => std::fs::rename(old, &s.target),
                None => std::fs::remove_file(&s.target),
            };
        }
        for old in backups.drain(..).flatten() {
            let _ = std::fs::remove_file(&old);
            unregister(list, &old);
        }
    };
    for s in &files {
        let backup = match std::fs::symlink_metadata(&s.target) {
            Ok(m) if m.is_file() => {
                let (stem, ext) = split_name(&s.target);
                let old = temporary_name(&s.target, &stem, &ext);
                list.push(old.clone());
                if let Err(e) = std::fs::hard_link(&s.target, &old).or_else(|_| std::fs::copy(&s.target, &old).map(drop)) {
                    backups.push(Some(old));
                    restore(&mut backups, &mut list, &[]);
                    return Err(io(&s.target)(e));
                }
                Some(old)
            }
            _ => None,
        };
        backups.push(backup);
    }
    for i in 0..files.len() {
        if let Err(e) = std::fs::rename(&files[i].temporary, &files[i].target) {
            let target = files[i].target.clone();
            restore(&mut backups, &mut list, &files[..i]);
            return Err(io(&target)(e));
        }
    }
    for s in files.iter_mut() {
        unregister(&mut list, &s.temporary);
        s.committed = true;
    }
    restore(&mut backups, &mut list, &[]);
    drop(list);
    for dir in files.iter().filter_map(|s| s.target.parent()).filter(|d| !d.as_os_str().is_empty()) {
        let _ = File::open(dir).and_then(|d| d.sync_all());
    }
    Ok(targets)
}

/// Write each `(target, bytes)` as the whole of its target, all or none
/// ([`commit_all`]): files that only make sense together.
pub fn write_all(files: &[(&Path, &[u8])]) -> Result<Vec<PathBuf>, OutputError> {
    let mut staged = Vec::with_capacity(files.len());
    for &(target, bytes) in files {
        let s = Staged::begin(target)?;
        File::create(s.temporary()).and_then(|mut f| f.write_all(bytes)).map_err(io(s.target()))?;
        staged.push(s);
    }
    commit_all(staged)
}

/// Whether two files hold the same bytes (false when either cannot be read).
pub fn same_bytes(a: &Path, b: &Path) -> bool {
    let (Ok(ma), Ok(mb)) = (std::fs::metadata(a), std::fs::metadata(b)) else { return false };
    if ma.len() != mb.len() {
        return false;
    }
    let (Ok(fa), Ok(fb)) = (File::open(a), File::open(b)) else { return false };
    let (mut fa, mut fb) = (std::io::BufReader::new(fa), std::io::BufReader::new(fb));
    let (mut ba, mut bb) = (vec![0u8; 1 << 16], vec![0u8; 1 << 16]);
    loop {
        let n = match fa.read(&mut ba) {
            Ok(0) => return fb.read(&mut bb[..1]).is_ok_and(|m| m == 0),
            Ok(n) => n,
            Err(_) => return false,
        };
        if fb.read_exact(&mut bb[..n]).is_err() || ba[..n] != bb[..n] {
            return false;
        }
    }
}

/// Temporary files of this target whose writer is gone (we hold the lock).
fn remove_stale_temporaries(directory: &Path, stem: &str, ext: &str) {
    let Ok(entries) = std::fs::read_dir(directory) else { return };
    for entry in entries.flatten() {
        if entry.file_name().to_str().is_some_and(|name| is_temporary_of(name, stem, ext)) {
            let _ = std::fs::remove_file(entry.path());
        }
    }
}

/// Write `bytes` as the whole of `target`, or leave it as it was.
pub fn write(target: impl AsRef<Path>, bytes: impl AsRef<[u8]>) -> Result<PathBuf, OutputError> {
    let staged = Staged::begin(target.as_ref())?;
    File::create(staged.temporary()).and_then(|mut f| f.write_all(bytes.as_ref())).map_err(io(staged.target()))?;
    staged.commit()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("kick-output-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    fn names(dir: &Path) -> Vec<String> {
        let mut v: Vec<String> = std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
        v.sort();
        v
    }

    #[test]
    fn temporary_names_are_recognised_exactly() {
        assert!(is_temporary_of("run.12-0.tmp.h5", "run", ".h5"));
        assert!(is_temporary_of("README.7-3.tmp", "README", ""));
        for other in ["run.h5", "run.h5.tmp", "run.12.tmp.h5", "run.1-2-3.tmp.h5", "run.a-0.tmp.h5", "runx.1-0.tmp.h5", "run.1-0.tmp.png"] {
            assert!(!is_temporary_of(other, "run", ".h5"), "{other}");
        }
    }

    #[test]
    fn a_second_writer_is_refused_and_nothing_is_left() {
        let dir = scratch("busy");
        let target = dir.join("a.h5");
        let first = Staged::begin(&target).unwrap();
        std::fs::write(first.temporary(), b"first").unwrap();
        let refused = Staged::begin(&target).err().expect("second writer must be refused");
        let message = refused.to_string();
        assert!(message.contains("a.h5") && message.contains(&format!("pid {}", std::process::id())), "{message}");
        // Another target in the same directory is independent.
        write(&dir.join("b.h5"), b"b").unwrap();
        first.commit().unwrap();
        assert_eq!(std::fs::read(&target).unwrap(), b"first");
        assert_eq!(names(&dir), ["a.h5", "b.h5"]);
        // Free again after the first ended.
        write(&target, b"second").unwrap();
        assert_eq!(std::fs::read(&target).unwrap(), b"second");
        assert_eq!(names(&dir), ["a.h5", "b.h5"]);
    }

    #[test]
    fn an_abandoned_write_keeps_the_old_file() {
        let dir = scratch("abandon");
        let target = dir.join("fig.png");
        write(&target, b"old").unwrap();
        {
            let staged = Staged::begin(&target).unwrap();
            std::fs::write(staged.temporary(), b"half").unwrap();
            assert!(staged.temporary().to_string_lossy().ends_with(".tmp.png"));
        }
        assert_eq!(std::fs::read(&target).unwrap(), b"old");
        assert_eq!(names(&dir), ["fig.png"]);
    }

    #[test]
    fn leftovers_of_a_killed_writer_are_taken_over() {
        let dir = scratch("stale");
        let target = dir.join("s.h5");
        // What a SIGKILLed writer leaves: an unlocked lock file and its temporary file.
        std::fs::write(lock_path(&target), b"999999").unwrap();
        std::fs::write(dir.join("s.999999-0.tmp.h5"), b"partial").unwrap();
        std::fs::write(dir.join("unrelated.999999-0.tmp.h5"), b"keep").unwrap();
        write(&target, b"whole").unwrap();
        assert_eq!(names(&dir), ["s.h5", "unrelated.999999-0.tmp.h5"]);
    }

    /// A write of the bytes a target already holds leaves it as it was (the
    /// same inode, no temporary file left); other bytes replace it; a
    /// predicate that calls two files the same keeps the old one.
    #[cfg(unix)]
    #[test]
    fn an_unchanged_file_is_not_rewritten() {
        use std::os::unix::fs::MetadataExt;
        let dir = scratch("unchanged");
        let target = dir.join("page.md");
        let inode = |p: &Path| std::fs::metadata(p).unwrap().ino();
        write(&target, b"same").unwrap();
        let first = inode(&target);
        write(&target, b"same").unwrap();
        assert_eq!(inode(&target), first, "identical bytes must not be written again");
        assert_eq!(names(&dir), ["page.md"]);
        // Same length, one byte different.
        write(&target, b"sane").unwrap();
        assert_ne!(inode(&target), first);
        assert_eq!(std::fs::read(&target).unwrap(), b"sane");
        let second = inode(&target);
        let staged = Staged::begin(&target).unwrap();
        std::fs::write(staged.temporary(), b"other content").unwrap();
        staged.commit_unless(|old, new| old == target.as_path() && new.to_string_lossy().contains(".tmp")).unwrap();
        assert_eq!((inode(&target), std::fs::read(&target).unwrap()), (second, b"sane".to_vec()));
        assert_eq!(names(&dir), ["page.md"]);
        // No target yet: the predicate is not asked.
        let fresh = dir.join("fresh.md");
        let staged = Staged::begin(&fresh).unwrap();
        std::fs::write(staged.temporary(), b"new").unwrap();
        staged.commit_unless(|_, _| true).unwrap();
        assert_eq!(std::fs::read(&fresh).unwrap(), b"new");
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn same_bytes_compares_every_byte() {
        let dir = scratch("same-bytes");
        let (a, b) = (dir.join("a"), dir.join("b"));
        let mut long = vec![7u8; 200_000];
        std::fs::write(&a, &long).unwrap();
        std::fs::write(&b, &long).unwrap();
        assert!(same_bytes(&a, &b));
        long[150_000] = 8;
        std::fs::write(&b, &long).unwrap();
        assert!(!same_bytes(&a, &b));
        std::fs::write(&b, &long[..199_999]).unwrap();
        assert!(!same_bytes(&a, &b));
        assert!(!same_bytes(&a, &dir.join("missing")));
        let _ = std::fs::remove_dir_all(&dir);
    }

    /// Another user's planted link at `NAME.h5.lock` (to a file, dangling, or
    /// a FIFO) is refused naming it; the file it points at is untouched.
    #[cfg(unix)]
    #[test]
    fn a_planted_lock_is_refused_never_written_through() {
        let dir = scratch("planted");
        let target = dir.join("run.h5");
        let victim = dir.join("victim.txt");
        std::fs::write(&victim, b"precious").unwrap();
        std::os::unix::fs::symlink(&victim, lock_path(&target)).unwrap();
        let message = write(&target, b"new").expect_err("a linked lock must be refused").to_string();
        assert!(message.contains("run.h5.lock") && message.contains("symbolic link"), "{message}");
        assert_eq!(std::fs::read(&victim).unwrap(), b"precious");
        assert!(std::fs::symlink_metadata(lock_path(&target)).unwrap().file_type().is_symlink(), "the link is left for the user to see");
        assert!(!target.exists());

        // Dangling: nothing is created where it points.
        let other = dir.join("other.h5");
        let nowhere = dir.join("nowhere");
        std::os::unix::fs::symlink(&nowhere, lock_path(&other)).unwrap();
        assert!(write(&other, b"new").is_err());
        assert!(!nowhere.exists() && !other.exists());

        // A hard link to another file is not ours to truncate.
        let third = dir.join("third.h5");
        std::fs::hard_link(&victim, lock_path(&third)).unwrap();
        let message = write(&third, b"new").expect_err("a hard-linked lock must be refused").to_string();
        assert!(message.contains("third.h5.lock") && message.contains("hard link"), "{message}");
        assert_eq!(std::fs::read(&victim).unwrap(), b"precious");

        // A FIFO: refused at once, not waited on.
        let fourth = dir.join("fourth.h5");
        let fifo = std::ffi::CString::new(lock_path(&fourth).to_str().unwrap()).unwrap();
        assert_eq!(unsafe { libc::mkfifo(fifo.as_ptr(), 0o600) }, 0);
        let message = write(&fourth, b"new").expect_err("a FIFO lock must be refused").to_string();
        assert!(message.contains("fourth.h5.lock") && message.contains("special file"), "{message}");
        let _ = std::fs::remove_dir_all(&dir);
    }

    /// Fault 1 of issue 33: `nodir/../a.h5` is `a.h5` once the writer has
    /// created `nodir`; before, only existing paths were resolved, so an
    /// input was replaced by a name through a missing directory.
    #[test]
    fn a_path_through_a_missing_directory_is_checked_as_it_will_resolve() {
        let dir = scratch("resolve");
        let input = dir.join("a.h5");
        std::fs::write(&input, b"input").unwrap();
        let sneaky = dir.join("nodir").join("..").join("a.h5");
        assert_eq!(resolve(&sneaky), resolve(&input));
        assert_eq!(resolve(&dir.join("x/y/../../a.h5")), resolve(&input));
        assert_eq!(resolve(&dir.join("./nodir/b.h5")), resolve(&dir).join("nodir/b.h5"));
        let message = check_output(&sneaky, "OUT", "h5", &[&input]).unwrap_err().to_string();
        assert!(message.contains("is the input") && message.contains("resolves to"), "{message}");
        assert!(!dir.join("nodir").exists(), "the check creates nothing");
        // A relative path from elsewhere, a link and a hard link to the input.
        #[cfg(unix)]
        {
            std::os::unix::fs::symlink(&input, dir.join("link.h5")).unwrap();
            std::fs::hard_link(&input, dir.join("hard.h5")).unwrap();
            for other in ["link.h5", "hard.h5"] {
                assert!(check_output(&dir.join(other), "OUT", "h5", &[&input]).is_err(), "{other}");
            }
        }
        // Another name beside it is fine.
        check_output(&dir.join("nodir/../b.h5"), "OUT", "h5", &[&input]).unwrap();
        let _ = std::fs::remove_dir_all(&dir);
    }

    /// A folder a command owns may not hold what it reads; a file target
    /// may not be a directory.
    #[test]
    fn folders_written_may_not_hold_inputs() {
        let dir = scratch("folder");
        let inputs = dir.join("experiments");
        std::fs::create_dir_all(&inputs).unwrap();
        let file = inputs.join("figure1.toml");
        std::fs::write(&file, b"x").unwrap();
        let folder = |p: &Path| check_paths(&[Target::Folder { flag: "--out", path: p }], &[&file]);
        let message = folder(&inputs).unwrap_err().to_string();
        assert!(message.contains("`--out`") && message.contains("holds the input"), "{message}");
        assert!(folder(&dir).is_err());
        assert!(folder(&dir.join("gone/../experiments")).is_err());
        folder(&dir.join("results")).unwrap();
        let message = check_paths(&[Target::File { flag: "--report", path: &inputs }], &[]).unwrap_err().to_string();
        assert!(message.contains("is a directory"), "{message}");
        let _ = std::fs::remove_dir_all(&dir);
    }

    /// Fault 4 of issue 33: files that belong together are written whole or
    /// not at all. A second target that cannot be written leaves the first
    /// as it was (before, the first was already renamed into place).
    #[test]
    fn a_pair_is_written_whole_or_not_at_all() {
        let dir = scratch("pair");
        let (csv, toml) = (dir.join("s.csv"), dir.join("s.toml"));
        write_all(&[(&csv, b"new csv"), (&toml, b"new toml")]).unwrap();
        assert_eq!(std::fs::read(&csv).unwrap(), b"new csv");
        // The second cannot begin (a directory in its place): nothing changes.
        std::fs::remove_file(&toml).unwrap();
        std::fs::create_dir(&toml).unwrap();
        assert!(write_all(&[(&csv, b"newer csv"), (&toml, b"newer toml")]).is_err());
        assert_eq!(std::fs::read(&csv).unwrap(), b"new csv");
        std::fs::remove_dir(&toml).unwrap();
        // The second rename fails after the first is done: the first is put back.
        std::fs::write(&toml, b"old toml").unwrap();
        let first = Staged::begin(&csv).unwrap();
        std::fs::write(first.temporary(), b"lost csv").unwrap();
        let second = Staged::begin(&toml).unwrap();
        std::fs::write(second.temporary(), b"lost toml").unwrap();
        std::fs::remove_file(&toml).unwrap();
        std::fs::create_dir(&toml).unwrap();
        std::fs::write(toml.join("keep"), b"x").unwrap();
        assert!(commit_all(vec![first, second]).is_err());
        assert_eq!(std::fs::read(&csv).unwrap(), b"new csv");
        assert_eq!(names(&dir), ["s.csv", "s.toml"]);
        // A new pair whose second fails leaves neither.
        let (a, b) = (dir.join("n.csv"), dir.join("s.toml"));
        assert!(write_all(&[(&a, b"a"), (&b, b"b")]).is_err());
        assert!(!a.exists());
        assert_eq!(names(&dir), ["s.csv", "s.toml"]);
        let _ = std::fs::remove_dir_all(&dir);
    }

    /// The temporary file exists, a regular file of ours, from `begin` on:
    /// its name cannot be taken by a link between `begin` and the writer.
    #[cfg(unix)]
    #[test]
    fn the_temporary_file_is_created_exclusively() {
        let dir = scratch("exclusive");
        let target = dir.join("t.h5");
        let staged = Staged::begin(&target).unwrap();
        assert!(std::fs::symlink_metadata(staged.temporary()).unwrap().file_type().is_file());
        let planted = std::os::unix::fs::symlink(dir.join("victim"), staged.temporary());
        assert_eq!(planted.err().map(|e| e.kind()), Some(std::io::ErrorKind::AlreadyExists));
        drop(staged);
        assert_eq!(names(&dir), Vec::<String>::new());
    }

    /// A link is written through to the regular file it names (it used to
    /// be replaced by a file); a link to a device is refused and left as it
    /// was; a path through a file names that file; a folder where no file
    /// can be made (/proc, root included) is refused by the flag before any
    /// work, and the probe leaves nothing behind.
    #[test]
    fn links_files_in_the_way_and_unwritable_folders() {
        let dir = scratch("links");
        let (real, link, device) = (dir.join("real.csv"), dir.join("link.csv"), dir.join("full.csv"));
        std::fs::write(&real, b"old").unwrap();
        std::os::unix::fs::symlink(&real, &link).unwrap();
        write(&link, b"new").unwrap();
        assert!(std::fs::symlink_metadata(&link).unwrap().file_type().is_symlink());
        assert_eq!(std::fs::read(&real).unwrap(), b"new");
        std::os::unix::fs::symlink("/dev/null", &device).unwrap();
        let message = write(&device, b"x").unwrap_err().to_string();
        assert!(message.contains("not to a regular file"), "{message}");
        assert!(std::fs::symlink_metadata(&device).unwrap().file_type().is_symlink());
        let message = write(real.join("sub/a.h5"), b"x").unwrap_err().to_string();
        assert!(message.contains(&format!("{} is a file, not a folder", real.display())), "{message}");
        let inside = real.join("a.h5");
        let message = check_paths(&[Target::File { flag: "--out", path: &inside }], &[]).unwrap_err().to_string();
        assert!(message.starts_with("`--out`") && message.contains("is a file, not a folder"), "{message}");
        let message = check_paths(&[Target::Folder { flag: "--out", path: &real }], &[]).unwrap_err().to_string();
        assert!(message.contains("it is a file, not a folder"), "{message}");
        let proc = Path::new("/proc/kick-probe.h5");
        let message = check_paths(&[Target::File { flag: "--history", path: proc }], &[]).unwrap_err().to_string();
        assert!(message.starts_with("`--history`") && message.contains("files cannot be made in /proc"), "{message}");
        assert!(check_paths(&[Target::File { flag: "--out", path: &dir.join("new/a.h5") }], &[]).is_ok());
        assert_eq!(names(&dir), ["full.csv", "link.csv", "real.csv"]);
    }
}
