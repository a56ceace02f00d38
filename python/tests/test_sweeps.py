"""Vectorised sweeps: numpy broadcasting and shapes, per-point masks, the same bits whatever
the threads and chunks, agreement with the single solves, the GIL released."""

import threading
import time

import mpmath
import numpy as np
import pytest

import moving_hertz as mh


def test_broadcast_shapes():
    r = mh.sweep_ellipses(np.array([[0.25], [0.3], [0.1]]), speed=0.9,
                          ratio=np.geomspace(0.1, 10, 4))
    assert r.shape == (3, 4) and r.k.shape == (3, 4) and r.iterations.shape == (3, 4)
    assert r.ok.all() and r.k.dtype == np.float64
    assert set(r.fields) == {"k", "e", "I1", "I2"}
    assert [mh.ROUTES[c] for c in np.unique(r.route)] == ["fixed-rule", "graded-rule"]


@pytest.mark.parametrize("ratio,shape", [
    (2.0, ()), (np.array(2.0), ()), (np.zeros(0), (0,)), (np.ones((3, 0)), (3, 0)),
    ([0.5, 2.0], (2,)), ((1, 2, 3), (3,)), (np.arange(1, 7, dtype=np.int32).reshape(2, 3), (2, 3)),
    (np.linspace(0.5, 4, 10, dtype=np.float32)[::3], (4,)),
    (np.asfortranarray(np.linspace(0.5, 4, 6).reshape(2, 3)), (2, 3)),
    (np.array(["0.5", "2"]), (2,)), (np.array([0.5, "1/3"], dtype=object), (2,)),
])
def test_shapes_and_dtypes(ratio, shape):
    """0-d, empty, lists, tuples, int32, float32 strided, Fortran order, str and object
    arrays: the broadcast shape, each point the single solve of its value."""
    r = mh.sweep_ellipses(0.25, speed=0.75, ratio=ratio)
    assert r.shape == shape and r.k.shape == shape
    flat = np.asarray(ratio, dtype=object).ravel()
    for i, x in enumerate(flat[:3]):
        x = float(x) if isinstance(x, (np.floating, np.integer, float, int)) else x
        single = mh.solve_ellipse(0.25, speed=0.75, ratio=x)
        got = r.k.ravel()[i]
        assert abs(got - single.k) <= (r.k_error.ravel()[i] + single.k_error) * single.k


def test_one_bad_point_is_masked():
    ratio = np.geomspace(0.01, 100, 1000)
    ratio[137] = np.nan
    ratio[500] = -1.0
    r = mh.sweep_ellipses(0.25, speed=0.9, ratio=ratio)
    assert (~r.ok).sum() == 2 and not r.ok[137] and not r.ok[500]
    assert "not finite" in r.messages[137] and "outside its domain" in r.messages[500]
    assert r.messages[0] is None and r.route[137] == -1 and r.iterations[500] == -1
    assert np.ma.count_masked(r.k) == 2 and np.isfinite(r.k.compressed()).all()
    assert (r.k_error.compressed() < 1e-13).all()


def test_bad_text_point_is_masked_with_its_message():
    r = mh.sweep_ellipses(["0.25", "0.7", "x"], gap=["1e-3", "1e-3", "1e-3"], ratio=2.0)
    assert r.ok.tolist() == [True, False, False]
    assert "0.7" in r.messages[1] and "x" in r.messages[2]
    r = mh.sweep_ellipses(0.25, gap=np.array(["1e-12", "0", "1.5"]), ratio=2.0)
    assert r.ok.tolist() == [True, False, False] and "gap" in r.messages[1]


def test_same_bits_whatever_the_threads_and_chunks():
    """A sweep of 40000 points (3 chunks) on 1 and 2 threads, and split at a multiple of the
    block (64): the same bits."""
    ratio = np.geomspace(1e-3, 1e3, 400)
    gap = np.geomspace(1e-1, 1e-8, 100)[:, None]
    one = mh.sweep_ellipses(0.25, gap=gap, ratio=ratio, threads=1)
    two = mh.sweep_ellipses(0.25, gap=gap, ratio=ratio, threads=2)
    assert one.ok.all()
    assert np.array_equal(one.k.data, two.k.data) and np.array_equal(one.e.data, two.e.data)
    flat_gap = np.broadcast_to(gap, (100, 400)).ravel()
    flat_ratio = np.broadcast_to(ratio, (100, 400)).ravel()
    cut = 64 * 300
    tail = mh.sweep_ellipses(0.25, gap=flat_gap[cut:], ratio=flat_ratio[cut:])
    assert np.array_equal(tail.k.data, one.k.data.ravel()[cut:])


def test_sweep_result_pickles():
    import pickle

    r = mh.sweep_ellipses(0.25, speed=0.9, ratio=[0.5, -1.0])
    back = pickle.loads(pickle.dumps(r))
    assert back.shape == (2,) and back.k[0] == r.k[0] and back.messages[1] == r.messages[1]
    with pytest.raises(AttributeError):
        back.k = None


def test_sweep_agrees_with_single_solves_above_f64():
    ratio = ["0.01", "0.5", "2", "100"]
    r = mh.sweep_ellipses("0.3", speed="0.99", ratio=ratio, precision="dd")
    t = mh.sweep_ellipses("0.3", speed="0.99", ratio=ratio, precision="dd", as_text=True)
    assert r.k.dtype == object and type(r.k[0]) is mpmath.mpf and type(t.k[0]) is str
    for i, x in enumerate(ratio):
        s = mh.solve_ellipse("0.3", speed="0.99", ratio=x, precision="dd")
        with mpmath.workprec(106):
            assert r.k[i] == mpmath.mpf(t.k[i])
            assert abs(r.k[i] - s.k) <= (r.k_error[i] + s.k_error) * s.k
            assert r.k_error[i] < mpmath.mpf("1e-28")


def test_contact_and_integral_sweeps():
    c = mh.sweep_contacts(0.3, speed=[0.0, 0.5, 0.9], radius_along=0.05,
                          radius_across=[[0.02], [0.05]], load=1000.0, shear_modulus=80e9)
    assert c.shape == (2, 3) and c.ok.all()
    s = mh.solve_contact(0.3, speed=0.9, radius_along=0.05, radius_across=0.02, load=1000.0,
                         shear_modulus=80e9)
    assert abs(c.a[0, 2] - s.a) <= (c.a_error[0, 2] + s.a_error) * s.a
    assert np.allclose(c.load.data, 1000.0, rtol=1e-13)
    i = mh.sweep_integrals(0.25, speed=0.999, k=np.array([0.5, 2.0, -1.0]), derivatives=True)
    assert i.ok.tolist() == [True, True, False] and "dI1_dk" in i.fields and "J0" not in i.fields
    one = mh.integrals(0.25, speed=0.999, k=2.0, derivatives=True)
    assert abs(i.I2[1] - one.I2) <= (i.I2_error[1] + one.I2_error) * one.I2
    assert i.work[1] > 0


def test_progress_callback():
    calls = []
    r = mh.sweep_ellipses(0.25, speed=0.9, ratio=np.geomspace(0.1, 10, 20000),
                          progress=lambda done, total: calls.append((done, total)))
    # One call a chunk of 4096 points (64 blocks of 64).
    assert r.ok.all() and calls[-1] == (20000, 20000) and len(calls) == 5

    def stop(done, total):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        mh.sweep_ellipses(0.25, speed=0.9, ratio=np.ones(20000), progress=stop)
    with pytest.raises(mh.DomainError):
        mh.sweep_ellipses(0.25, speed=0.9, ratio=1.0, progress=3)
    with pytest.raises(mh.DomainError):
        mh.sweep_ellipses(0.25, speed=0.9, ratio=1.0, threads=0)


def _runs_beside(work):
    """How often the main thread ran (1 ms sleeps) while ``work`` ran in another thread: with
    the GIL held through the native call it could not run at all until the call returned."""
    done = threading.Event()

    def run():
        work()
        done.set()

    t = threading.Thread(target=run)
    t.start()
    ticks = 0
    while not done.is_set():
        ticks += 1
        time.sleep(0.001)
    t.join()
    return ticks


def test_sweeps_release_the_gil():
    """A heartbeat thread beats while the main thread is inside the native sweep: between the
    progress calls after the first and the second chunk only native code runs, and a thread
    holding the GIL there would leave no beat in that window."""
    beats, marks, stop = [], [], threading.Event()

    def heart():
        while not stop.is_set():
            beats.append(time.perf_counter())
            time.sleep(0.0005)

    h = threading.Thread(target=heart)
    h.start()
    try:
        mh.sweep_ellipses(0.25, gap=1e-9, ratio=np.geomspace(0.01, 100, 3 * 4096), threads=1,
                          precision="dd",
                          progress=lambda done, total: marks.append(time.perf_counter()))
    finally:
        stop.set()
        h.join()
    assert len(marks) == 3
    inside = [b for b in beats if marks[0] + 0.001 < b < marks[1] - 0.001]
    assert len(inside) >= 3, (len(inside), marks[1] - marks[0])


def test_two_threads_sweeps_overlap():
    """Two sweeps started together in two threads run at the same time (their spans overlap)
    while the main thread keeps running."""
    ratio = np.geomspace(0.01, 100, 2000)
    spans = []

    def timed():
        t0 = time.perf_counter()
        mh.sweep_ellipses(0.25, gap=1e-6, ratio=ratio, precision="dd", threads=1, as_text=True)
        spans.append((t0, time.perf_counter()))

    def two():
        threads = [threading.Thread(target=timed) for _ in range(2)]
        for t in threads:
            t.start()
        for t in threads:
            t.join()

    assert _runs_beside(two) >= 5
    (a0, a1), (b0, b1) = spans
    assert b0 < a1 and a0 < b1, spans


def test_single_solves_release_the_gil():
    """A 4096-bit solve in a thread leaves the interpreter free: the main thread runs
    meanwhile."""
    assert _runs_beside(lambda: mh.solve_ellipse(0.25, speed="0.999", ratio=2,
                                                 precision=4096)) >= 5


STEEL = dict(youngs_modulus=210e9, density=7850.0)  # c_R = 2974.82 m/s at nu = 0.3


def test_velocity_sweep_equals_solve_contact_point_by_point():
    v = np.array([0.0, 800.0, 2000.0, 2974.0, 2974.9, 3500.0])
    r2 = np.array([0.02, 0.1])[:, None]
    c = mh.sweep_contacts(0.3, velocity=v, radius_along=0.05, radius_across=r2, load=1000.0,
                          **STEEL)
    assert c.shape == (2, 6)
    assert c.ok.tolist() == [[True] * 4 + [False] * 2] * 2
    for i, j in np.ndindex(c.shape):
        if not c.ok[i, j]:
            assert "c_R" in c.messages[i, j] and c.route[i, j] == -1, c.messages[i, j]
            with pytest.raises(mh.DomainError, match="c_R"):
                mh.solve_contact(0.3, velocity=v[j], radius_along=0.05,
                                 radius_across=r2[i, 0], load=1000.0, **STEEL)
            continue
        s = mh.solve_contact(0.3, velocity=v[j], radius_along=0.05, radius_across=r2[i, 0],
                             load=1000.0, **STEEL)
        for f in ("a", "b", "p0", "d0", "load"):
            got, err = getattr(c, f)[i, j], getattr(c, f + "_error")[i, j]
            want, want_err = getattr(s, f), getattr(s, f + "_error")
            assert abs(got - want) <= (err + want_err) * want, (f, i, j)
        assert abs(c.e[i, j] - s.e) <= c.e_error[i, j] + s.e_error
    # The speed changes the shape: a at 2974 m/s against a static punch.
    assert c.a[0, 3] != c.a[0, 0]


def test_velocity_sweep_in_text_at_double_double():
    c = mh.sweep_contacts("0.3", velocity=["2960.6", "2960.7"], radius_along="0.05",
                          radius_across="0.02", approach="1e-5", shear_modulus="80e9",
                          density="7850", precision="dd", as_text=True)
    s = mh.solve_contact("0.3", velocity="2960.6", radius_along="0.05", radius_across="0.02",
                         approach="1e-5", shear_modulus="80e9", density="7850",
                         precision="dd", as_text=True)
    assert c.ok.tolist() == [True, False] and "c_R" in c.messages[1]
    with mpmath.workprec(106):
        a, want = mpmath.mpf(c.a[0]), mpmath.mpf(s.a)
        assert abs(a - want) <= (mpmath.mpf(c.a_error[0]) + mpmath.mpf(s.a_error)) * want


def test_youngs_and_shear_moduli_give_the_same_sweep():
    # E = 2(1 + nu) mu exactly (nu = 0.25): mu = E/(2(1 + nu)) is mu again, bit for bit.
    mu, e = 1e9, 2.5e9
    speeds = dict(speed=np.array([0.0, 0.5, 0.99]))
    velocities = dict(velocity=np.array([100.0, 500.0, 570.0]), density=1000.0)
    for given in (speeds, velocities):
        kw = dict(radius_along=0.05, radius_across=np.array([[0.02], [0.2]]), load=10.0,
                  **given)
        by_mu = mh.sweep_contacts(0.25, shear_modulus=mu, **kw)
        by_e = mh.sweep_contacts(0.25, youngs_modulus=e, **kw)
        assert by_mu.ok.all()
        for f in by_mu.fields:
            assert np.array_equal(getattr(by_mu, f).data, getattr(by_e, f).data), f
    # A Young's modulus is not a shear modulus: E taken as mu gives another contact.
    wrong = mh.sweep_contacts(0.25, shear_modulus=e, **kw)
    assert not np.array_equal(wrong.a.data, by_mu.a.data)


def test_contact_sweep_arguments_are_checked_as_solve_contact_checks_them():
    kw = dict(radius_along=0.05, radius_across=0.02, load=1000.0)
    with pytest.raises(mh.DomainError, match="density"):
        mh.sweep_contacts(0.3, velocity=[100.0], youngs_modulus=210e9, **kw)
    with pytest.raises(mh.DomainError, match="density"):
        mh.sweep_contacts(0.3, speed=[0.5], shear_modulus=80e9, density=7850.0, **kw)
    with pytest.raises(mh.DomainError, match="exactly one of shear_modulus"):
        mh.sweep_contacts(0.3, speed=[0.5], shear_modulus=80e9, youngs_modulus=210e9, **kw)
    with pytest.raises(mh.DomainError, match="exactly one of speed"):
        mh.sweep_contacts(0.3, speed=[0.5], velocity=[1.0], shear_modulus=80e9, **kw)
    bad = mh.sweep_contacts(0.3, velocity=[100.0, -1.0], density=[7850.0, 7850.0],
                            youngs_modulus=[210e9, 210e9], **kw)
    assert bad.ok.tolist() == [True, False] and "velocity" in bad.messages[1]
    bad = mh.sweep_contacts(0.3, velocity=100.0, density=[7850.0, -1.0],
                            youngs_modulus=210e9, **kw)
    assert bad.ok.tolist() == [True, False] and "density" in bad.messages[1]


def test_a_scalar_input_gives_the_sweep_of_its_repeated_array():
    # A scalar travels as one value (not repeated); the points are the same, bit for bit.
    ratio = np.geomspace(1e-2, 1e2, 300)
    one = mh.sweep_ellipses(0.25, gap=1e-3, ratio=ratio)
    full = mh.sweep_ellipses(np.full(300, 0.25), gap=np.full(300, 1e-3), ratio=ratio)
    for f in ("k", "k_error", "e", "I1", "I2"):
        assert np.array_equal(getattr(one, f).data, getattr(full, f).data), f
    text = mh.sweep_ellipses("0.25", gap="1e-3", ratio=ratio[:70], precision="dd", as_text=True)
    text_full = mh.sweep_ellipses(["0.25"] * 70, gap=["1e-3"] * 70, ratio=ratio[:70],
                                  precision="dd", as_text=True)
    assert list(text.k) == list(text_full.k) and text.ok.all()
    c = mh.sweep_contacts(0.3, velocity=np.array([100.0, 3000.0]), radius_along=0.05,
                          radius_across=0.02, load=1.0, youngs_modulus=210e9, density=7850.0)
    assert c.ok.tolist() == [True, False]
    empty = mh.sweep_ellipses(0.25, speed=0.5, ratio=np.array([]))
    assert empty.shape == (0,) and empty.k.size == 0


def test_progress_true_draws_a_tqdm_bar(monkeypatch):
    """``progress=True`` drives a ``tqdm.auto.tqdm`` bar to the sweep's total (a stand-in
    module records what the package asks of it), and without tqdm it is refused by name."""
    import sys
    import types

    bars = []

    class Bar:
        def __init__(self, total, unit):
            self.total, self.n, self.unit, self.closed = total, 0, unit, False
            bars.append(self)

        def update(self, k):
            self.n += k

        def close(self):
            self.closed = True

    fake = types.ModuleType("tqdm.auto")
    fake.tqdm = Bar
    monkeypatch.setitem(sys.modules, "tqdm", types.ModuleType("tqdm"))
    monkeypatch.setitem(sys.modules, "tqdm.auto", fake)
    r = mh.sweep_ellipses(0.25, speed=0.9, ratio=np.geomspace(0.1, 10, 9000), progress=True)
    assert r.ok.all() and len(bars) == 1
    assert (bars[0].n, bars[0].total, bars[0].unit, bars[0].closed) == (9000, 9000, "pt", True)
    monkeypatch.setitem(sys.modules, "tqdm.auto", None)
    with pytest.raises(mh.DomainError, match="tqdm"):
        mh.sweep_ellipses(0.25, speed=0.9, ratio=[0.5, 2.0], progress=True)
