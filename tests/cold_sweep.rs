//! Cold starts from several threads at once: the first solves of a process build the
//! Gauss–Legendre rules inside `OnceLock` initializers, while a sweep's workers on `rayon`'s
//! global pool wait on the same cells. A rule construction that handed its nodes to that pool
//! from a thread outside it would wait for workers that wait for it.
//!
//! Each trial needs a fresh process (the rules are process-wide): the test runs the ignored
//! `one_cold_start` in child processes of this binary and fails when one of them does not finish
//! within [`LIMIT`] or fails.

use moving_hertz::prelude::*;
use moving_hertz::sweep::{self, EllipsePoint, SpeedGiven};

mod common;
use common::{independent, within};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// Far above what one trial takes (under a second, release build) and far below CI's limit.
const LIMIT: Duration = Duration::from_secs(60);

/// Child processes run; each is one cold start.
const TRIALS: usize = 12;

/// `n` points of one ν and four speeds, log-spaced ratios from 10⁻³ to 10³ (`n`/4 a speed).
fn points<T: Real>(p: T::Prec, n: usize) -> Vec<EllipsePoint<T>> {
    let x = |v: f64| T::from_f64(v, p);
    let speeds = [0.0, 0.5, 0.9, 0.999].map(|m| SpeedGiven::Mr(x(m)));
    let per = n / speeds.len();
    let ratios: Vec<T> = (0..per)
        .map(|j| x(10f64.powf(6.0 * j as f64 / (per - 1) as f64 - 3.0)))
        .collect();
    EllipsePoint::grid(&[x(0.25)], &speeds, &ratios)
}

/// One cold start: a double-double sweep on the global pool while this thread solves points
/// of the same sweep on its own; every point Ok and within the bounds of its independent solve.
#[test]
#[ignore = "one trial of cold_starts_from_several_threads_finish, in a process of its own"]
fn one_cold_start() {
    let pts = points::<Dd>((), 4 * sweep::BLOCK);
    let swept = std::thread::scope(|s| {
        let sweeping = s.spawn(|| sweep::ellipses(&pts, &Options::default()));
        pts.iter().step_by(37).for_each(|pt| {
            independent(pt).unwrap();
        });
        sweeping.join().unwrap()
    });
    for (pt, got) in pts.iter().zip(&swept) {
        let want = independent(pt).unwrap();
        assert!(within(got.as_ref().unwrap(), &want) <= 1.0, "{pt:?}");
    }
}

#[test]
fn cold_starts_from_several_threads_finish() {
    let exe = std::env::current_exe().unwrap();
    for trial in 0..TRIALS {
        let mut child = Command::new(&exe)
            .args(["--ignored", "--exact", "one_cold_start", "--test-threads=1"])
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap();
        let start = Instant::now();
        let status = loop {
            if let Some(status) = child.try_wait().unwrap() {
                break Some(status);
            }
            if start.elapsed() > LIMIT {
                let _ = child.kill();
                break None;
            }
            std::thread::sleep(Duration::from_millis(10));
        };
        match status {
            Some(s) => assert!(s.success(), "trial {trial}: {s}"),
            None => panic!("trial {trial}: a cold start did not finish within {LIMIT:?}"),
        }
    }
}
