//! The `progress=True` bar of the `*_many` functions: indicatif's bar drawn
//! on Python's `sys.stderr` (so a notebook, a redirected `sys.stderr` and
//! pytest see it, as they see tqdm's), counting rows done. Only the calling
//! thread draws, from the interruptible runner's signal loop; the workers
//! count rows in an atomic and never touch Python.

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle, TermLike};
use pyo3::prelude::*;
use std::io;
use std::sync::Mutex;

/// Redraws a second on a terminal; off one (a log file) one a second, so a
/// long run does not fill the log with updates.
const TERMINAL_HZ: u8 = 10;
const LOG_HZ: u8 = 1;

/// Python's `sys.stderr` as indicatif's terminal: writes gathered until
/// `flush`, then written with the GIL taken once. A failed write (no
/// `sys.stderr`, a closed one) is dropped: the bar never fails a call.
#[derive(Debug)]
struct PythonStderr {
    width: u16,
    pending: Mutex<String>,
}

impl PythonStderr {
    fn push(&self, s: &str) -> io::Result<()> {
        if let Ok(mut pending) = self.pending.lock() {
            pending.push_str(s);
        }
        Ok(())
    }
}

impl TermLike for PythonStderr {
    fn width(&self) -> u16 {
        self.width
    }
    fn move_cursor_up(&self, n: usize) -> io::Result<()> {
        if n > 0 {
            self.push(&format!("\x1b[{n}A"))?;
        }
        Ok(())
    }
    fn move_cursor_down(&self, n: usize) -> io::Result<()> {
        if n > 0 {
            self.push(&format!("\x1b[{n}B"))?;
        }
        Ok(())
    }
    fn move_cursor_right(&self, n: usize) -> io::Result<()> {
        if n > 0 {
            self.push(&format!("\x1b[{n}C"))?;
        }
        Ok(())
    }
    fn move_cursor_left(&self, n: usize) -> io::Result<()> {
        if n > 0 {
            self.push(&format!("\x1b[{n}D"))?;
        }
        Ok(())
    }
    fn write_line(&self, s: &str) -> io::Result<()> {
        self.push(s)?;
        self.push("\n")
    }
    fn write_str(&self, s: &str) -> io::Result<()> {
        self.push(s)
    }
    // A carriage return only: the bar pads its line to the width, so the
    // next draw overwrites all of it, in a terminal and in a notebook alike.
    fn clear_line(&self) -> io::Result<()> {
        self.push("\r")
    }
    fn flush(&self) -> io::Result<()> {
        let text = match self.pending.lock() {
            Ok(mut pending) => std::mem::take(&mut *pending),
            Err(_) => return Ok(()),
        };
        if !text.is_empty() {
            Python::attach(|py| write_stderr(py, &text));
        }
        Ok(())
    }
}

/// Write `text` to `sys.stderr` and flush it, ignoring a failure.
fn write_stderr(py: Python<'_>, text: &str) {
    if let Ok(stderr) = py.import("sys").and_then(|sys| sys.getattr("stderr")) {
        if !stderr.is_none() {
            let _ = stderr.call_method1("write", (text,));
            let _ = stderr.call_method0("flush");
        }
    }
}

/// A bar of `total` rows labelled `label` (the function), drawn on
/// `sys.stderr`: as wide as its terminal (80 columns off one).
pub(crate) fn bar(py: Python<'_>, total: u64, label: &str) -> ProgressBar {
    let terminal = py
        .import("sys")
        .and_then(|sys| sys.getattr("stderr"))
        .and_then(|e| e.call_method0("isatty"))
        .and_then(|t| t.extract::<bool>())
        .unwrap_or(false);
    let columns = py
        .import("shutil")
        .and_then(|s| s.call_method0("get_terminal_size"))
        .and_then(|size| size.getattr("columns"))
        .and_then(|c| c.extract::<u16>())
        .unwrap_or(80);
    // One column short of the edge: a full line would wrap on some terminals.
    let term = PythonStderr { width: columns.clamp(40, 200) - 1, pending: Mutex::new(String::new()) };
    let hz = if terminal { TERMINAL_HZ } else { LOG_HZ };
    let bar = ProgressBar::with_draw_target(Some(total), ProgressDrawTarget::term_like_with_hz(Box::new(term), hz));
    if let Ok(style) = ProgressStyle::with_template("{msg} [{bar:30}] {pos}/{len} rows, {elapsed} (eta {eta})") {
        bar.set_style(style.progress_chars("=> "));
    }
    bar.set_message(label.to_string());
    bar
}

/// End the bar: at `done` rows (all of them, or where Ctrl-C stopped the
/// call), drawn once more, and the line ended so what follows starts on its own.
pub(crate) fn end(py: Python<'_>, bar: &ProgressBar, done: u64) {
    bar.set_position(done);
    bar.abandon();
    write_stderr(py, "\n");
}
