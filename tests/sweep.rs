//! Sweeps (`moving_hertz::sweep`): every point within its error bound of the independent solve
//! of the same point (and, at double-double, of a 256-bit solve), results identical on 1 and 4
//! threads and when a sweep is split at block boundaries, invalid points as their own typed
//! errors.

use moving_hertz::prelude::*;
use moving_hertz::sweep::{self, EllipsePoint, SpeedGiven, BLOCK};
use moving_hertz::{solve_ellipse, Ellipse, Error, Integrals};

mod common;
use common::{independent, within};

/// ν from −0.9 to 0.5, speeds from rest to 1 − M_R = 10⁻¹⁰, A1/B1 log-spaced over `decades`
/// either side of 1 with `per_curve` points.
fn grid<T: Real>(p: T::Prec, per_curve: usize, decades: f64) -> Vec<EllipsePoint<T>> {
    let x = |v: f64| T::from_f64(v, p);
    let nus = [-0.9, 0.0, 0.25, 0.5].map(x);
    let speeds = [
        SpeedGiven::Mr(x(0.0)),
        SpeedGiven::Mr(x(0.7)),
        SpeedGiven::Gap(x(1e-4)),
        SpeedGiven::Gap(x(1e-10)),
        SpeedGiven::Text("0.999999".into()),
    ];
    let ratios: Vec<T> = (0..per_curve)
        .map(|j| x(10f64.powf(decades * (2.0 * j as f64 / (per_curve - 1) as f64 - 1.0))))
        .collect();
    EllipsePoint::grid(&nus, &speeds, &ratios)
}

/// Every point of the sweep is Ok and within its error bound of the independent solve
/// ([`common::independent`]: the point alone, 64 bits above the sweep's precision); the
/// sweep's bounds are as tight as a single solve's at its own precision (within a factor 4).
fn check_against_independent<T: Real + Send + Sync>(points: &[EllipsePoint<T>]) {
    let swept = sweep::ellipses(points, &Options::default());
    assert_eq!(swept.len(), points.len());
    let mut worst = 0f64;
    for (pt, got) in points.iter().zip(&swept) {
        let want = independent(pt).unwrap();
        let got = got.as_ref().unwrap_or_else(|e| panic!("{pt:?}: {e}"));
        let w = within(got, &want);
        assert!(w <= 1.0, "{pt:?}: k {:?} vs {:?}", got.k(), want.k());
        let single = single_solve(pt);
        assert!(
            got.k().error.to_f64() <= 4.0 * single.k().error.to_f64(),
            "{pt:?}: bound {} vs {}",
            got.k().error,
            single.k().error
        );
        worst = worst.max(w);
    }
    eprintln!("{} points, worst |dk| / bounds = {worst:.3}", points.len());
}

/// The point solved alone at its own precision (`solve_ellipse`, default options).
fn single_solve<T: Real>(pt: &EllipsePoint<T>) -> Ellipse<T> {
    let mat = Material::new(pt.nu.clone()).unwrap();
    let speed = match &pt.speed {
        SpeedGiven::Mr(m) => mat.speed(m.clone()),
        SpeedGiven::Gap(g) => mat.speed_from_gap(g.clone()),
        SpeedGiven::Text(m) => mat.parse_speed(m),
        _ => unreachable!("the grids of this check have no velocities"),
    };
    solve_ellipse(&speed.unwrap(), &pt.ratio, &Options::default()).unwrap()
}

#[test]
fn every_point_within_its_bound_of_the_independent_solve_f64() {
    check_against_independent(&grid::<f64>((), 60, 6.0));
}

#[test]
fn every_point_within_its_bound_of_the_independent_solve_dd() {
    check_against_independent(&grid::<Dd>((), 16, 6.0));
}

#[test]
fn every_point_within_its_bound_of_the_independent_solve_256() {
    let p = MpPrec::new(256).unwrap();
    let pts: Vec<_> = grid::<Mp>(p, 6, 3.0).into_iter().step_by(2).collect();
    check_against_independent(&pts);
}

/// Speeds given as velocities (m/s) in a half-space of E and ρ at each ν: every point within
/// its bound of the independent solve, and a velocity at or above that ν's c_R
/// refused in its own row, naming c_R, while the other rows are solved.
#[test]
fn velocity_points_within_their_bounds_and_refused_above_rayleigh() {
    let moduli = Moduli::Youngs {
        youngs_modulus: 210e9,
        density: 7850.0,
    };
    let speeds: Vec<_> = [0.0, 1500.0, 2000.0, 2974.0, 2980.0]
        .map(|velocity| SpeedGiven::Velocity { velocity, moduli })
        .into();
    let ratios = [0.1, 0.4, 1.0, 2.5, 10.0];
    let pts = EllipsePoint::grid(&[0.25, 0.3, 0.5], &speeds, &ratios);
    let swept = sweep::ellipses(&pts, &Options::default());
    let (mut solved, mut refused) = (0, 0);
    for (pt, got) in pts.iter().zip(&swept) {
        let mat = Material::new(pt.nu).unwrap();
        let c_r = *Solid::new(&mat, moduli).unwrap().c_r();
        let SpeedGiven::Velocity { velocity, .. } = pt.speed else {
            unreachable!()
        };
        match got {
            Ok(got) => {
                assert!(velocity < c_r, "{pt:?} solved above c_R = {c_r}");
                // The same inputs, exactly, 64 bits above f64.
                let want = independent(pt).unwrap();
                assert!(
                    within(got, &want) <= 1.0,
                    "{pt:?}: k {:?} vs {:?}",
                    got.k(),
                    want.k()
                );
                solved += 1;
            }
            Err(e) => {
                assert!(velocity >= c_r, "{pt:?}: {e}");
                assert!(e.to_string().contains("c_R = 2"), "{e}");
                refused += 1;
            }
        }
    }
    // c_R = 3007.5 m/s at ν = 0.25, 2974.8 at 0.3, 2852.7 at 1/2 (E fixed: μ falls as ν rises).
    assert_eq!((solved, refused), (60, 15));
}

/// At double-double the sweep's k is within its bound of a 256-bit solve of the same
/// (double-double) inputs: continuation keeps the ladder's accuracy.
#[test]
fn double_double_sweep_against_256_bits() {
    let p = MpPrec::new(256).unwrap();
    let pts = grid::<Dd>((), 12, 4.0);
    let swept = sweep::ellipses(&pts, &Options::default());
    for (pt, got) in pts.iter().zip(&swept) {
        let got = got.as_ref().unwrap();
        let up = |x: &Dd| Mp::from_float(&x.to_float(106), p);
        let hi = EllipsePoint {
            nu: up(&pt.nu),
            speed: match &pt.speed {
                SpeedGiven::Mr(m) => SpeedGiven::Mr(up(m)),
                SpeedGiven::Gap(g) => SpeedGiven::Gap(up(g)),
                SpeedGiven::Text(m) => SpeedGiven::Text(m.clone()),
                _ => unreachable!("the grid has no velocities"),
            },
            ratio: up(&pt.ratio),
        };
        let want = single_solve(&hi).k().value.clone();
        let err = ((up(&got.k().value) - &want) / &want).abs().to_f64();
        assert!(
            err <= got.k().error.to_f64(),
            "{pt:?}: error {err:e} > bound {}",
            got.k().error
        );
    }
}

/// k of every point, as bits (for comparisons bit for bit).
fn bits<T: Real>(r: &[moving_hertz::Result<Ellipse<T>>]) -> Vec<String> {
    r.iter()
        .map(|e| match e {
            Ok(e) => format!("{} {}", e.k().value.to_decimal(), e.k().error),
            Err(e) => e.to_string(),
        })
        .collect()
}

fn on_threads<R: Send>(n: usize, f: impl FnOnce() -> R + Send) -> R {
    rayon::ThreadPoolBuilder::new()
        .num_threads(n)
        .build()
        .unwrap()
        .install(f)
}

/// The same results on 1, 4 and 16 threads, on 2 threads bound to CPUs, and from a sweep split
/// at a multiple of [`BLOCK`].
fn check_reproducible<T: Real + Send + Sync>(pts: &[EllipsePoint<T>]) {
    let opts = Options::default();
    let one = bits(&on_threads(1, || sweep::ellipses(pts, &opts)));
    let four = bits(&on_threads(4, || sweep::ellipses(pts, &opts)));
    assert_eq!(one, four);
    let sixteen = bits(&on_threads(16, || sweep::ellipses(pts, &opts)));
    assert_eq!(one, sixteen);
    let bound = rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .start_handler(|i| {
            sweep::bind_to_cpu(i);
        })
        .build()
        .unwrap();
    assert_eq!(one, bits(&bound.install(|| sweep::ellipses(pts, &opts))));
    let cut = 2 * BLOCK;
    let mut split = bits(&sweep::ellipses(&pts[..cut], &opts));
    split.extend(bits(&sweep::ellipses(&pts[cut..], &opts)));
    assert_eq!(one, split);
}

#[test]
fn same_bits_on_one_four_and_sixteen_threads() {
    check_reproducible(&grid::<f64>((), 40, 5.0));
    check_reproducible(&grid::<Dd>((), 12, 5.0));
    let p = MpPrec::new(256).unwrap();
    check_reproducible(&grid::<Mp>(p, 20, 2.0)[..3 * BLOCK]);
}

/// k, e, their bounds and the evaluation count of every point, as text (for comparisons bit for
/// bit), or its error.
fn full_bits<T: Real>(r: &[moving_hertz::Result<Ellipse<T>>]) -> Vec<String> {
    r.iter()
        .map(|e| match e {
            Ok(e) => format!(
                "{} {} {} {} {}",
                e.k().value.to_decimal(),
                e.k().error,
                e.e().value.to_decimal(),
                e.e().error,
                e.iterations()
            ),
            Err(e) => e.to_string(),
        })
        .collect()
}

/// `ellipses_at` at speeds formed once for all their points (each curve's speed shared by
/// every block of it, and warmed beforehand by a sweep of the points in reverse order) gives
/// the bits of `ellipses`, whose blocks form their own speeds: k, e, their bounds and the
/// evaluation count of every point, on 1 and 4 threads; a speed that failed to form (ν = 0.7)
/// is its points' error.
fn check_shared_speeds<T: Real + Send + Sync>(p: T::Prec, per_curve: usize) {
    let x = |v: f64| T::from_f64(v, p);
    let mut pts = grid::<T>(p, per_curve, 3.0);
    let ratios: Vec<T> = pts[..per_curve].iter().map(|pt| pt.ratio.clone()).collect();
    pts.extend(EllipsePoint::grid(
        &[x(0.7)],
        &[SpeedGiven::Mr(x(0.5))],
        &ratios,
    ));
    let opts = Options::default();
    let own = full_bits(&on_threads(2, || sweep::ellipses(&pts, &opts)));
    let speeds: Vec<_> = (pts.chunks(per_curve))
        .map(|c| Material::new(c[0].nu.clone()).and_then(|m| c[0].speed.speed_in(&m)))
        .collect();
    let at: Vec<_> = (pts.iter().enumerate())
        .map(|(j, pt)| sweep::AtSpeed {
            speed: &speeds[j / per_curve],
            ratio: &pt.ratio,
        })
        .collect();
    let reversed: Vec<_> = (at.iter().rev())
        .map(|a| sweep::AtSpeed {
            speed: a.speed,
            ratio: a.ratio,
        })
        .collect();
    on_threads(4, || sweep::ellipses_at(&reversed, &opts));
    for threads in [1, 4] {
        let shared = full_bits(&on_threads(threads, || sweep::ellipses_at(&at, &opts)));
        assert_eq!(own, shared, "{threads} threads");
    }
    assert!(own[own.len() - 1].contains("nu"), "{}", own[own.len() - 1]);
}

#[test]
fn shared_speeds_give_the_bits_of_ellipses() {
    check_shared_speeds::<f64>((), 3 * BLOCK + 5);
    check_shared_speeds::<Dd>((), BLOCK + 7);
}

/// A sweep called while another thread of its pool is busy with unrelated work finishes on
/// the free thread (its blocks are spawned jobs that a busy thread never has to take), with the
/// same bits as on one thread: the busy thread here waits for the sweep's own end, which a
/// sweep that needed every thread of the pool would never reach.
#[test]
fn a_busy_pool_thread_does_not_hold_up_a_sweep() {
    let pts = grid::<f64>((), 40, 5.0);
    let opts = Options::default();
    let alone = bits(&on_threads(1, || sweep::ellipses(&pts, &opts)));
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build()
        .unwrap();
    let (release, wait) = std::sync::mpsc::channel::<()>();
    let (started, is_busy) = std::sync::mpsc::channel::<()>();
    pool.spawn(move || {
        started.send(()).unwrap();
        let _ = wait.recv();
    });
    is_busy.recv().unwrap();
    let (done, result) = std::sync::mpsc::channel();
    let (pts2, opts2) = (pts.clone(), opts.clone());
    std::thread::spawn(move || {
        let r = pool.install(|| sweep::ellipses(&pts2, &opts2));
        let _ = done.send(bits(&r));
    });
    let got = result.recv_timeout(std::time::Duration::from_secs(30));
    let _ = release.send(());
    assert_eq!(got.expect("the sweep waited for the busy thread"), alone);
}

/// `bind_to_cpu` leaves a thread on one CPU (the standard library's count of the CPUs a thread
/// may run on reads the same affinity mask), and refuses an index past the CPUs.
#[test]
fn bind_to_cpu_leaves_one_cpu() {
    let (bound, after, past) = std::thread::spawn(|| {
        let past = sweep::bind_to_cpu(usize::MAX);
        let bound = sweep::bind_to_cpu(0);
        let after = std::thread::available_parallelism().map_or(0, |n| n.get());
        (bound, after, past)
    })
    .join()
    .unwrap();
    assert!(!past);
    if cfg!(target_os = "linux") {
        assert!(bound);
        assert_eq!(after, 1);
    } else {
        assert!(!bound);
    }
}

/// A sweep of one block runs on the caller's thread, where above 448 bits its solves put their
/// node loops on every core: the same bits as the same sweep on a pool thread (loops serial).
#[test]
fn one_block_on_the_callers_thread_same_bits() {
    let p = MpPrec::new(512).unwrap();
    let pts = &grid::<Mp>(p, 4, 2.0)[..6];
    let opts = Options::default();
    let here = bits(&sweep::ellipses(pts, &opts));
    let pooled = bits(&on_threads(1, || sweep::ellipses(pts, &opts)));
    assert_eq!(here, pooled);
    assert_eq!(here.len(), 6);
}

/// ν = 0.7, a ratio of 0 and a NaN ratio in the middle of a curve: those points' own typed
/// errors; every other point Ok and within its bounds of the sweep of the valid curve.
#[test]
fn an_invalid_point_fails_alone() {
    let valid = grid::<f64>((), 50, 3.0)[..100].to_vec();
    let mut bad = valid.clone();
    bad[17].nu = 0.7;
    bad[40].ratio = 0.0;
    bad[41].ratio = f64::NAN;
    let opts = Options::default();
    let good = sweep::ellipses(&valid, &opts);
    let got = sweep::ellipses(&bad, &opts);
    for (i, (g, w)) in got.iter().zip(&good).enumerate() {
        match (i, g) {
            (17, Err(Error::Domain { name, value, .. })) => {
                assert!(name.contains("nu") && value == "0.7", "{name} {value}")
            }
            (40, Err(Error::Domain { name, .. })) => assert!(name.contains("A1/B1")),
            (41, Err(Error::NotFinite { name, .. })) => assert!(name.contains("A1/B1")),
            (17 | 40 | 41, other) => panic!("point {i}: {other:?}"),
            (_, g) => {
                assert!(w.is_ok());
                assert!(within(g.as_ref().unwrap(), &independent(&valid[i]).unwrap()) <= 1.0)
            }
        }
    }
}

/// Contact solutions along a load curve and I1, I2 over a grid of k: within their bounds of the
/// one-by-one calls.
#[test]
fn contacts_and_integrals_as_one_by_one() {
    let speed = Material::new(0.3).unwrap().speed(0.95).unwrap();
    let problems: Vec<ContactProblem<f64>> = (0..80)
        .map(|j| ContactProblem {
            speed: speed.clone(),
            radius_along: 0.05,
            radius_across: 0.05 * 10f64.powf(-2.0 + j as f64 / 20.0),
            loading: Loading::Load(10f64.powf(j as f64 / 40.0)),
            shear_modulus: 80e9,
        })
        .collect();
    let swept = sweep::contacts(&problems, &Options::default());
    for (pb, got) in problems.iter().zip(&swept) {
        let (got, want) = (
            got.as_ref().unwrap(),
            pb.solve(&Options::default()).unwrap(),
        );
        let d = (got.a().value / want.a().value - 1.0).abs();
        assert!(
            d <= got.a().error.to_f64() + want.a().error.to_f64(),
            "a {} vs {}",
            got.a().value,
            want.a().value
        );
    }
    let ks: Vec<f64> = (1..=200).map(|j| j as f64 / 50.0).collect();
    let opts = IntegralOptions {
        derivatives: true,
        ..Default::default()
    };
    let swept: Vec<Integrals<f64>> = sweep::integrals(&speed, &ks, &opts)
        .into_iter()
        .map(Result::unwrap)
        .collect();
    for (k, got) in ks.iter().zip(&swept) {
        let want = moving_hertz::integrals(&speed, k, &opts).unwrap();
        for (g, w) in [(&got.i1, &want.i1), (&got.i2, &want.i2)] {
            let bound = g.error.to_f64() + w.error.to_f64();
            assert!(
                (g.value / w.value - 1.0).abs() <= bound,
                "k = {k}: {g:?} vs {w:?}"
            );
        }
    }
}

/// Empty inputs give empty results (no block, no work), and a sweep of one point (a block
/// shorter than [`BLOCK`]) gives that point's result.
#[test]
fn empty_and_single_point_sweeps() {
    let opts = Options::default();
    let speed = Material::new(0.25).unwrap().speed(0.9).unwrap();
    assert!(sweep::ellipses::<f64>(&[], &opts).is_empty());
    assert!(sweep::contacts::<f64>(&[], &opts).is_empty());
    assert!(sweep::integrals::<f64>(&speed, &[], &IntegralOptions::default()).is_empty());
    let one = EllipsePoint::grid(&[0.25], &[SpeedGiven::Mr(0.9)], &[0.5]);
    let swept = sweep::ellipses(&one, &opts);
    let want = independent(&one[0]).unwrap();
    assert_eq!(swept.len(), 1);
    assert!(within(swept[0].as_ref().unwrap(), &want) <= 1.0);
}

/// `try_contacts`: a problem that could not be formed (a velocity above c_R) keeps its error, in
/// place, across two blocks; every other point within its bounds of the one-by-one solve; and
/// with no errors the same bits as `contacts`.
#[test]
fn try_contacts_keeps_each_formation_error_in_place() {
    let moduli = Moduli::Youngs {
        youngs_modulus: "210e9",
        density: "7850",
    };
    let steel = Solid::<f64>::parse("0.3", moduli, ()).unwrap();
    let mu = *steel.shear_modulus().unwrap();
    let velocity = |j: usize| match j {
        5 | 64 | 70 => "3000".to_string(),
        _ => format!("{}", 100 + 25 * j),
    };
    let formed: Vec<moving_hertz::Result<ContactProblem<f64>>> = (0..80)
        .map(|j| {
            Ok(ContactProblem {
                speed: steel.parse_velocity(&velocity(j))?,
                radius_along: 0.05,
                radius_across: 0.02,
                loading: Loading::Load(1000.0),
                shear_modulus: mu,
            })
        })
        .collect();
    let opts = Options::default();
    let swept = sweep::try_contacts(&formed, &opts);
    assert_eq!(swept.len(), 80);
    for (j, (f, got)) in formed.iter().zip(&swept).enumerate() {
        match (f, got) {
            (Err(e), Err(g)) => {
                assert!([5, 64, 70].contains(&j), "{j}");
                assert_eq!(e.to_string(), g.to_string());
                assert!(g.to_string().contains("c_R") && g.to_string().contains("3000"));
            }
            (Ok(pb), Ok(got)) => {
                let want = pb.solve(&opts).unwrap();
                for (g, w) in [
                    (got.a(), want.a()),
                    (got.p0(), want.p0()),
                    (got.d0(), want.d0()),
                ] {
                    let d = (g.value / w.value - 1.0).abs();
                    assert!(d <= g.error.to_f64() + w.error.to_f64(), "{j}: {g:?} {w:?}");
                }
            }
            (f, g) => panic!("point {j}: formed {f:?}, solved {g:?}"),
        }
    }
    let valid: Vec<ContactProblem<f64>> = formed.into_iter().filter_map(Result::ok).collect();
    let wrapped: Vec<_> = valid.iter().cloned().map(Ok).collect();
    let (by_try, by_contacts) = (
        sweep::try_contacts(&wrapped, &opts),
        sweep::contacts(&valid, &opts),
    );
    for (t, c) in by_try.iter().zip(&by_contacts) {
        let (t, c) = (t.as_ref().unwrap(), c.as_ref().unwrap());
        assert_eq!(
            (t.a().value, t.p0().value, t.k().value),
            (c.a().value, c.p0().value, c.k().value)
        );
    }
}
