//! Faults around result files (issue 13): two writers of one file, a run
//! stopped by SIGINT, SIGTERM or SIGKILL. The result file is always one whole
//! run and no temporary or lock file is left behind.

use kick_store::SweepData;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

fn kick() -> Command {
    let mut command = Command::new(env!("CARGO_BIN_EXE_kick"));
    command.current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."));
    command
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("kick-reliability-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn names(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    v.sort();
    v
}

/// `kick sweep` of `samples` scenarios on one thread into `out`.
fn sweep(samples: u64, out: &Path) -> Command {
    let mut command = kick();
    command.args(["sweep", "--samples", &samples.to_string(), "--threads", "1", "--out", out.to_str().unwrap()]);
    command
}

/// A running kick, killed if the test fails before it ends (a sweep left
/// running would fill the disk).
struct Running(Option<Child>);

impl Running {
    fn id(&self) -> u32 {
        self.0.as_ref().unwrap().id()
    }
    fn finish(mut self) -> std::process::Output {
        self.0.take().unwrap().wait_with_output().unwrap()
    }
}

impl Drop for Running {
    fn drop(&mut self) {
        if let Some(child) = &mut self.0 {
            let _ = child.kill();
            let _ = child.wait();
        }
    }
}

fn start(mut command: Command) -> Running {
    Running(Some(command.stdout(Stdio::null()).stderr(Stdio::piped()).spawn().expect("kick starts")))
}

/// Wait until a file whose name contains `part` appears in `dir`.
fn wait_for(dir: &Path, part: &str) {
    let started = Instant::now();
    while !names(dir).iter().any(|n| n.contains(part)) {
        assert!(started.elapsed() < Duration::from_secs(60), "no `{part}` in {dir:?}: {:?}", names(dir));
        std::thread::sleep(Duration::from_millis(10));
    }
}

fn signal(child: &Running, signal: i32) {
    let pid = i32::try_from(child.id()).unwrap();
    // SAFETY: kill(2) on our own child's pid has no memory effects.
    assert_eq!(unsafe { libc::kill(pid, signal) }, 0);
}

#[test]
fn a_second_writer_of_the_same_file_is_refused_and_the_first_completes() {
    let dir = scratch("two");
    let out = dir.join("s.h5");
    let rows = 100_000;
    let first = start(sweep(rows, &out));
    wait_for(&dir, "tmp");
    let second = sweep(rows, &out).output().unwrap();
    let first = first.finish();
    assert!(first.status.success(), "{}", String::from_utf8_lossy(&first.stderr));
    assert!(!second.status.success(), "a second writer of {out:?} must be refused");
    let message = String::from_utf8_lossy(&second.stderr);
    assert!(message.contains(out.to_str().unwrap()) && message.contains("another process"), "{message}");
    // One whole run: every row there and readable.
    let data = SweepData::read(&out).unwrap();
    assert_eq!(data.rows() as u64, rows);
    assert_eq!(data.sets[0].status.len() as u64, rows);
    assert_eq!(names(&dir), ["s.h5"]);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn writers_started_together_leave_one_whole_file() {
    let dir = scratch("together");
    let out = dir.join("s.h5");
    let rows = 50_000;
    let children: Vec<Running> = (0..2).map(|_| start(sweep(rows, &out))).collect();
    let outputs: Vec<_> = children.into_iter().map(Running::finish).collect();
    assert!(outputs.iter().any(|o| o.status.success()));
    for o in outputs.iter().filter(|o| !o.status.success()) {
        let message = String::from_utf8_lossy(&o.stderr);
        assert!(message.contains("another process"), "{message}");
    }
    assert_eq!(SweepData::read(&out).unwrap().rows() as u64, rows);
    assert_eq!(names(&dir), ["s.h5"]);
    let _ = std::fs::remove_dir_all(&dir);
}

/// A long run into a file that exists, stopped by `sig` once it is writing.
fn interrupt(name: &str, sig: i32) -> (PathBuf, std::process::ExitStatus, Vec<u8>) {
    let dir = scratch(name);
    let out = dir.join("s.h5");
    assert!(sweep(20, &out).output().unwrap().status.success());
    let before = std::fs::read(&out).unwrap();
    // 2e6 rows (370 MB), stopped within a second of starting.
    let child = start(sweep(2_000_000, &out));
    wait_for(&dir, "tmp");
    std::thread::sleep(Duration::from_millis(200));
    signal(&child, sig);
    let status = child.finish().status;
    assert_eq!(std::fs::read(&out).unwrap(), before, "the existing result file changed");
    (dir, status, before)
}

#[test]
fn sigint_and_sigterm_remove_the_temporary_file_and_keep_the_old_result() {
    for (sig, code) in [(libc::SIGINT, 130), (libc::SIGTERM, 143)] {
        let (dir, status, _) = interrupt(&format!("signal{sig}"), sig);
        assert_eq!(status.code(), Some(code), "signal {sig}: {status:?}");
        assert_eq!(names(&dir), ["s.h5"], "signal {sig}");
        let _ = std::fs::remove_dir_all(&dir);
    }
}

#[test]
fn sigkill_keeps_the_old_result_and_the_next_run_clears_what_it_left() {
    use std::os::unix::process::ExitStatusExt;
    let (dir, status, before) = interrupt("kill", libc::SIGKILL);
    assert_eq!(status.signal(), Some(libc::SIGKILL));
    assert!(SweepData::read(&dir.join("s.h5")).is_ok());
    // Its temporary and lock files stay (nothing runs after SIGKILL); the
    // next writer of the file takes the lock over and removes them.
    let out = dir.join("s.h5");
    assert!(sweep(30, &out).output().unwrap().status.success());
    assert_ne!(std::fs::read(&out).unwrap(), before);
    assert_eq!(SweepData::read(&out).unwrap().rows(), 30);
    assert_eq!(names(&dir), ["s.h5"]);
    let _ = std::fs::remove_dir_all(&dir);
}

/// Largest resident set of any child of this test process so far, bytes.
/// Runs `command` to its end, its stdout and stderr into files in `dir`:
/// its status, stdout, stderr and the largest VmHWM (peak resident set of
/// its own address space) seen while it ran, polled every 2 ms. Neither
/// RUSAGE_CHILDREN nor wait4 will do: Rust spawns with vfork, so a child's
/// maxrss starts at this test process's own peak (the other tests' memory).
fn output_and_peak_rss(command: &mut Command, dir: &Path) -> (std::process::ExitStatus, Vec<u8>, Vec<u8>, u64) {
    let (out, err) = (dir.join("stdout"), dir.join("stderr"));
    let mut child = command.stdout(std::fs::File::create(&out).unwrap()).stderr(std::fs::File::create(&err).unwrap()).spawn().unwrap();
    let status_file = format!("/proc/{}/status", child.id());
    let mut peak = 0;
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status;
        }
        let hwm = std::fs::read_to_string(&status_file).ok().and_then(|text| {
            let line = text.lines().find(|l| l.starts_with("VmHWM:"))?;
            line.split_whitespace().nth(1)?.parse::<u64>().ok()
        });
        peak = peak.max(hwm.unwrap_or(0) * 1024);
        std::thread::sleep(Duration::from_millis(2));
    };
    let (stdout, stderr) = (std::fs::read(&out).unwrap(), std::fs::read(&err).unwrap());
    std::fs::remove_file(&out).unwrap();
    std::fs::remove_file(&err).unwrap();
    (status, stdout, stderr, peak)
}

/// `kick simulate --history FILE --interval 2e-8` (2.7e5 rows, 60 MB) and
/// `kick simulate3d --history FILE --interval 2e-8` (2.6e5 rows, 58 MB) stream
/// their rows: the file is whole, stdout holds only the summary, and the
/// process's memory stays far below the file's size.
#[test]
fn long_histories_are_streamed_to_the_file() {
    let dir = scratch("history");
    let mut peak = 0;
    for (command, interval, file, least_rows) in [("simulate", "2e-8", "h1.csv", 260_000usize), ("simulate3d", "2e-8", "h3.csv", 260_000)] {
        let path = dir.join(file);
        let (status, stdout, stderr, rss) = output_and_peak_rss(
            kick().args([command, "--history", path.to_str().unwrap(), "--interval", interval, "--format", "json"]),
            &dir,
        );
        assert!(status.success(), "{}", String::from_utf8_lossy(&stderr));
        peak = peak.max(rss);
        let summary: serde_json::Value = serde_json::from_slice(&stdout).expect("stdout is the JSON summary alone");
        assert!(summary.get("history").is_none());
        // Read line by line: this process's memory would count for the next child's (fork).
        use std::io::BufRead;
        let rows = std::io::BufReader::new(std::fs::File::open(&path).unwrap()).lines().count() - 1;
        let bytes = std::fs::metadata(&path).unwrap().len();
        println!("{command}: {rows} rows, {bytes} bytes");
        assert!(rows > least_rows, "{command}: {rows} rows");
        assert!(bytes > 50_000_000, "{command}: {bytes} bytes");
    }
    println!("peak resident set {peak} bytes");
    assert!(peak < 50_000_000, "peak resident set of kick: {peak} bytes");
    assert_eq!(names(&dir), ["h1.csv", "h3.csv"]);
    let _ = std::fs::remove_dir_all(&dir);
}

/// A sweep beyond the row bound and a thread count beyond the machine's
/// are refused at once, naming the setting (both used to start).
#[test]
fn oversized_sweeps_and_thread_counts_are_refused_before_starting() {
    let dir = scratch("caps");
    let out = dir.join("s.h5");
    for (args, named) in [
        (vec!["--samples", "1000000000000"], "samples = 1000000000000"),
        (vec!["--samples", "10", "--threads", "5000"], "`--threads` = 5000"),
        (vec!["--samples", "10", "--threads", "20000"], "`--threads` = 20000"),
    ] {
        let mut command = kick();
        command.args(["sweep", "--out", out.to_str().unwrap()]).args(&args);
        // A run that started is stopped by the guard: the test must not run it to its end.
        let mut child = start(command);
        let started = Instant::now();
        while child.0.as_mut().unwrap().try_wait().unwrap().is_none() {
            assert!(started.elapsed() < Duration::from_secs(20), "{args:?} still running after 20 s");
            std::thread::sleep(Duration::from_millis(20));
        }
        let output = child.finish();
        let message = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(1), "{args:?} must be refused: {message}");
        assert!(message.contains(named), "{message}");
    }
    assert!(names(&dir).is_empty(), "{:?}", names(&dir));
    let _ = std::fs::remove_dir_all(&dir);
}

/// A large run states its rows and estimated bytes on stderr before it starts.
#[test]
fn a_large_run_states_its_size_first() {
    use std::io::BufRead;
    let dir = scratch("large");
    let out = dir.join("s.h5");
    let mut child = start(sweep(1_000_000, &out));
    let mut line = String::new();
    let stderr = child.0.as_mut().unwrap().stderr.take().unwrap();
    std::io::BufReader::new(stderr).read_line(&mut line).unwrap();
    signal(&child, libc::SIGTERM);
    assert_eq!(child.finish().status.code(), Some(143));
    // 185 bytes a row: 8 parameters, 15 outcomes, a status byte.
    assert!(line.contains("1000000 rows, about 185 MB") && line.contains("s.h5"), "{line}");
    assert!(names(&dir).is_empty(), "{:?}", names(&dir));
    let _ = std::fs::remove_dir_all(&dir);
}

/// Fault 15 of issue 33: a write the system refuses part way (here a file
/// size limit, `ulimit -f`, the way a full disk refuses) says what happened
/// and which file, in words: no HDF5 function names, buffer addresses or
/// "bytes actually written = 18446744073709551615". Nothing is left behind.
#[cfg(unix)]
#[test]
fn a_write_the_system_refuses_says_what_and_which_file() {
    let dir = scratch("limit");
    let out = dir.join("s.h5");
    // SIGXFSZ ignored, so the write fails with EFBIG instead of killing kick.
    let script = format!("trap '' XFSZ; ulimit -f 64; exec \"$0\" sweep --samples 3000 --threads 1 --out '{}'", out.display());
    let output = Command::new("sh")
        .args(["-c", &script, env!("CARGO_BIN_EXE_kick")])
        .current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
        .output()
        .unwrap();
    let message = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(1), "{message}");
    assert!(message.contains(&out.display().to_string()) && message.contains("File too large"), "{message}");
    for internal in ["H5", "bytes actually written", "buf =", "file descriptor", "errno"] {
        assert!(!message.contains(internal), "`{internal}` in {message}");
    }
    assert!(names(&dir).is_empty(), "{:?}", names(&dir));
    let _ = std::fs::remove_dir_all(&dir);
}
