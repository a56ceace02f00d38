"""moving_hertz.dask: a dask.array whose blocks are the crate's sweeps, bit for bit the
in-process sweep, on the default scheduler and on a LocalCluster of 2 worker processes."""

import numpy as np
import pytest

import moving_hertz as mh

dask = pytest.importorskip("dask")  # the test command installs dask; skipped only without it
distributed = pytest.importorskip("distributed")
import moving_hertz.dask as mhd  # noqa: E402


def _equal(structured, r):
    for f in r.fields:
        for n in (f, f + "_error"):
            a, b = structured[n], getattr(r, n).data
            if a.dtype == object:  # decimal text above f64: every digit
                assert list(a.ravel()) == list(b.ravel()), n
            else:
                assert np.array_equal(a, b, equal_nan=True), n
    assert np.array_equal(structured["iterations"], r.iterations)
    assert np.array_equal(structured["route"], r.route)
    assert np.array_equal(structured["ok"], r.ok)
    assert list(structured["message"].ravel()) == list(r.messages.ravel())


GAP = np.geomspace(1e-1, 1e-9, 7)[:, None]
RATIO = np.geomspace(1e-3, 1e3, 150)


def test_chunk_points_follow_the_cost():
    sizes = [mhd.chunk_points(p) for p in ("f64", "dd", 256, 1024)]
    assert all(s % 64 == 0 for s in sizes) and sizes == sorted(sizes, reverse=True)
    assert sizes[-1] >= 64


def test_default_scheduler_equals_in_process():
    ratio = RATIO.copy()
    ratio[17] = -1.0
    lazy = mhd.sweep_ellipses(0.25, gap=GAP, ratio=ratio, chunk=128)
    assert lazy.shape == (7, 150) and lazy.numblocks != (1,)
    _equal(lazy.compute(), mh.sweep_ellipses(0.25, gap=GAP, ratio=ratio))


def test_local_cluster_of_two_processes_equals_in_process():
    from distributed import Client, LocalCluster

    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                      dashboard_address=None) as cluster, Client(cluster) as client:
        lazy = mhd.sweep_ellipses(0.25, gap=GAP, ratio=RATIO, chunk=192)
        got = client.compute(lazy).result()
        hi = mhd.sweep_contacts("0.3", speed=["0.5", "0.9"], radius_along="0.05",
                                radius_across=np.array(["0.02", "0.05", "0.1"])[:, None],
                                load="1000", shear_modulus="80e9", precision=256, chunk=64)
        got_hi = client.compute(hi).result()
        assert len(client.scheduler_info()["workers"]) == 2
    _equal(got, mh.sweep_ellipses(0.25, gap=GAP, ratio=RATIO))
    kw = dict(speed=["0.5", "0.9"], radius_along="0.05", load="1000", shear_modulus="80e9",
              radius_across=np.array(["0.02", "0.05", "0.1"])[:, None], precision=256)
    _equal(got_hi, mh.sweep_contacts("0.3", as_text=True, **kw))
    values = mhd.numbers(got_hi, 256)
    in_process = mh.sweep_contacts("0.3", **kw)
    assert all(x._mpf_ == y._mpf_ for x, y in zip(values["a"].ravel(), in_process.a.ravel()))


def test_velocity_contact_sweep_equals_in_process():
    velocity = np.linspace(0.0, 3100.0, 150)  # c_R = 2974.82 m/s: the last points fail
    kw = dict(velocity=velocity, radius_along=0.05, radius_across=np.array([[0.02], [0.1]]),
              load=1000.0, youngs_modulus=210e9, density=7850.0)
    lazy = mhd.sweep_contacts(0.3, chunk=64, **kw)
    assert lazy.shape == (2, 150) and lazy.numblocks != (1,)
    got = lazy.compute()
    in_process = mh.sweep_contacts(0.3, **kw)
    assert not in_process.ok.all() and in_process.ok[:, :100].all()
    _equal(got, in_process)
    hi = mhd.sweep_contacts("0.3", velocity=["2000", "2960.6", "2960.7"], radius_along="0.05",
                           radius_across="0.02", load="1000", shear_modulus="80e9",
                           density="7850", precision=256).compute()
    _equal(hi, mh.sweep_contacts("0.3", velocity=["2000", "2960.6", "2960.7"],
                                 radius_along="0.05", radius_across="0.02", load="1000",
                                 shear_modulus="80e9", density="7850", precision=256,
                                 as_text=True))
    assert hi["ok"].tolist() == [True, True, False] and "c_R" in hi["message"][2]
