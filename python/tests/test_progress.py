"""progress= on long calls: the numbers equal a call without it to the bit; the callback
sees increasing counts that end at the total."""
import numpy as np
import pytest

import hillstab

PAIR = dict(mass=np.diag([1.0, 0.64]), b=[[1.1, -0.1], [-0.1, 0.9]], cos=-np.diag([1.0, 0.8]))


def same(first, second, names):
    for name in names:
        a, b = np.asarray(first[name]), np.asarray(second[name])
        assert a.dtype == b.dtype and a.shape == b.shape, name
        assert np.array_equal(a.view(np.uint8), b.view(np.uint8)), name


def counts():
    seen = []
    return seen, lambda done, total: seen.append((done, total))


def increasing_to(seen, total):
    assert seen, "never called"
    done = [d for d, t in seen]
    assert all(t == total for d, t in seen)
    assert all(b > a for a, b in zip(done, done[1:])) and done[-1] == total


@pytest.mark.parametrize("threads", [1, 2])
def test_floquet_in_chunks(threads):
    rng = np.random.default_rng(7)
    alpha, beta = rng.uniform(0.0, 9.8, 2500), rng.uniform(-2.0, 12.0, 2500)
    whole = hillstab.floquet(alpha, beta, model="elastic", epsilon=0.05, threads=threads)
    seen, report = counts()
    parts = hillstab.floquet(alpha, beta, model="elastic", epsilon=0.05, threads=threads, progress=report, chunk=300)
    same(whole, parts, list(whole.names) + ["status"])
    increasing_to(seen, 2500)
    assert [d for d, t in seen] == list(range(300, 2500, 300)) + [2500]


def test_floquet_chunk_error_counts_from_the_whole_call():
    alpha = np.r_[np.full(50, 1.0), 10.0]
    with pytest.raises(ValueError, match=r"^point 50 \(alpha = 10.0"):
        hillstab.floquet(alpha, 1.0, model="elastic", progress=lambda d, t: None, chunk=7)


@pytest.mark.parametrize("threads", [1, 2])
def test_chart_rows(threads):
    grid = ((0.0, 9.8, 60), (-2.0, 12.0, 90))
    whole = hillstab.chart(*grid, model="elastic", method="magnus6", threads=threads)
    seen, report = counts()
    watched = hillstab.chart(*grid, model="elastic", method="magnus6", threads=threads, progress=report)
    same(whole, watched, list(whole.names) + ["status", "alpha", "beta"])
    increasing_to(seen, 60)


def test_chart_error_before_any_row():
    seen, report = counts()
    with pytest.raises(ValueError, match="got alpha = 10.0"):
        hillstab.chart((0.0, 10.0, 5), (0.0, 1.0, 3), model="elastic", progress=report)
    assert seen == []


def test_system_points_and_chart():
    pair = hillstab.System(**PAIR)
    rng = np.random.default_rng(3)
    alpha, beta = rng.uniform(0.0, 1.5, 300), rng.uniform(0.0, 3.0, 300)
    whole = pair.points(alpha, beta, epsilon=0.1, threads=2)
    seen, report = counts()
    parts = pair.floquet(alpha, beta, epsilon=0.1, threads=2, progress=report, chunk=64)
    same(whole, parts, whole.names)
    increasing_to(seen, 300)
    whole = pair.chart((0.0, 1.5, 31), (0.0, 3.0, 41), threads=2)
    seen, report = counts()
    watched = pair.chart((0.0, 1.5, 31), (0.0, 3.0, 41), threads=2, progress=report)
    same(whole, watched, list(whole.names) + ["alpha", "beta"])
    increasing_to(seen, 31)


def test_progress_true_and_bad_values(capsys):
    r = hillstab.floquet(np.linspace(0.0, 9.0, 30), 2.0, model="elastic", progress=True, chunk=10)
    assert r.trace.shape == (30,)
    try:
        import tqdm  # noqa: F401
    except ImportError:
        assert "30 of 30 points" in capsys.readouterr().err
    with pytest.raises(TypeError, match="progress"):
        hillstab.floquet(1.0, 2.0, model="elastic", progress="yes")
    with pytest.raises(ValueError, match="chunk"):
        hillstab.floquet(1.0, 2.0, model="elastic", progress=True, chunk=0)
