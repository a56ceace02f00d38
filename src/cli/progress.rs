//! A progress bar on stderr, shown only once the work has taken more than a second.

use std::io::Write;
use std::time::Instant;

pub struct Progress {
    label: String,
    total: usize,
    done: usize,
    start: Instant,
    shown: bool,
}

impl Progress {
    pub fn new(label: impl Into<String>, total: usize) -> Progress {
        Progress {
            label: label.into(),
            total: total.max(1),
            done: 0,
            start: Instant::now(),
            shown: false,
        }
    }

    /// `n` more items done: the bar is redrawn when a percent is passed (the clock is read
    /// only then).
    pub fn advance(&mut self, n: usize) {
        let step = (self.total / 100).max(1);
        let before = self.done;
        self.done += n;
        if before / step == self.done / step && self.done != self.total {
            return;
        }
        let elapsed = self.start.elapsed().as_secs_f64();
        if elapsed < 1.0 && !self.shown {
            return;
        }
        self.shown = true;
        let frac = self.done as f64 / self.total as f64;
        let width = 40;
        let filled = (frac * width as f64).round() as usize;
        let eta = if frac > 0.0 {
            elapsed * (1.0 - frac) / frac
        } else {
            0.0
        };
        eprint!(
            "\r{} [{}{}] {:3.0}%  {:.0}s left ",
            self.label,
            "#".repeat(filled),
            ".".repeat(width - filled),
            100.0 * frac,
            eta
        );
        let _ = std::io::stderr().flush();
    }

    pub fn finish(&self) {
        if self.shown {
            eprintln!(
                "\r{} done in {:.1} s{}",
                self.label,
                self.start.elapsed().as_secs_f64(),
                " ".repeat(40)
            );
        }
    }
}
