//! Everything `kick` prints goes through [`Out`]: a reader that stops early
//! (`kick check | head -1`) closes the pipe, and the rest of the output is
//! dropped quietly instead of failing the command.

use clap::ValueEnum;
use kick_study::Printable;
use std::io::{self, Write};

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Format {
    Text,
    Json,
}

/// Errors reach `main` as text naming the problem.
pub type CliResult = Result<(), String>;

/// Standard output; after a broken pipe every write succeeds without output.
pub struct Out {
    stdout: io::Stdout,
    closed: bool,
}

impl Out {
    pub fn new() -> Out {
        Out { stdout: io::stdout(), closed: false }
    }

    fn quiet(&mut self, result: io::Result<usize>, len: usize) -> io::Result<usize> {
        match result {
            Err(e) if e.kind() == io::ErrorKind::BrokenPipe => {
                self.closed = true;
                Ok(len)
            }
            other => other,
        }
    }

    /// `value` as text or JSON, then the files it wrote on stderr. A result
    /// outside its contact law's validity is printed whole (its status
    /// says so) and then is an error: the command exits 1, as a fit that did
    /// not converge does, so no script takes it for an ordinary result.
    pub fn print<T: Printable>(&mut self, format: Format, value: &T) -> CliResult {
        let text = match format {
            Format::Text => value.text(),
            Format::Json => kick_study::json(value)?,
        };
        self.write_all(text.as_bytes()).map_err(|e| format!("cannot write to standard output: {e}"))?;
        self.flush().map_err(|e| format!("cannot write to standard output: {e}"))?;
        for path in value.written() {
            note(&format!("wrote {}", path.display()));
        }
        if let Some(why) = value.no_answer() {
            return Err(why);
        }
        match value.outside_validity() {
            Some(why) => Err(format!("the result above is {why}")),
            None => Ok(()),
        }
    }
}

impl Write for Out {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        if self.closed {
            return Ok(buf.len());
        }
        let result = self.stdout.write(buf);
        self.quiet(result, buf.len())
    }

    fn flush(&mut self) -> io::Result<()> {
        if self.closed {
            return Ok(());
        }
        let result = self.stdout.flush().map(|()| 0);
        self.quiet(result, 0).map(|_| ())
    }
}

/// One line on stderr; a closed stderr loses it, never the command.
pub fn note(line: &str) {
    let _ = writeln!(io::stderr(), "{line}");
}
