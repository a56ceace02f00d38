//! A progress bar on stderr, shown only when stderr is a terminal and once the work has taken
//! more than a second; advanced from any thread (the blocks of a sweep report as they are
//! solved).

use std::io::{IsTerminal, Write};
use std::sync::{Mutex, PoisonError};
use std::time::Instant;

pub struct Progress {
    label: String,
    total: usize,
    start: Instant,
    /// Whether stderr is a terminal: the bar is drawn only then (never into a file or pipe).
    terminal: bool,
    /// Items done, and whether the bar has been drawn.
    state: Mutex<(usize, bool)>,
}

impl Progress {
    pub fn new(label: impl Into<String>, total: usize) -> Progress {
        Progress {
            label: label.into(),
            total: total.max(1),
            start: Instant::now(),
            terminal: std::io::stderr().is_terminal(),
            state: Mutex::new((0, false)),
        }
    }

    /// `n` more items done: the bar is redrawn when a percent is passed (the clock is read
    /// only then).
    pub fn advance(&self, n: usize) {
        if !self.terminal {
            return;
        }
        let mut state = self.state.lock().unwrap_or_else(PoisonError::into_inner);
        let (done, shown) = &mut *state;
        let step = (self.total / 100).max(1);
        let before = *done;
        *done += n;
        if before / step == *done / step && *done != self.total {
            return;
        }
        let elapsed = self.start.elapsed().as_secs_f64();
        if elapsed < 1.0 && !*shown {
            return;
        }
        *shown = true;
        let frac = *done as f64 / self.total as f64;
        let width = 40;
        let filled = (frac * width as f64).round() as usize;
        let eta = if frac > 0.0 {
            elapsed * (1.0 - frac) / frac
        } else {
            0.0
        };
        let mut err = std::io::stderr().lock();
        let _ = write!(
            err,
            "\r{} [{}{}] {:3.0}%  {:.0}s left ",
            self.label,
            "#".repeat(filled),
            ".".repeat(width - filled),
            100.0 * frac,
            eta
        );
        let _ = err.flush();
    }

    pub fn finish(&self) {
        if self.state.lock().unwrap_or_else(PoisonError::into_inner).1 {
            let _ = writeln!(
                std::io::stderr(),
                "\r{} done in {:.1} s{}",
                self.label,
                self.start.elapsed().as_secs_f64(),
                " ".repeat(40)
            );
        }
    }
}
