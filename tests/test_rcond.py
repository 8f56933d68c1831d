"""The reciprocal condition number read at thresholds (assur.groups._rcond).

Against numpy's own, from the singular values of every matrix: matrices well
conditioned, near singular, exactly singular, not finite, scaled far from 1.
"""

from __future__ import annotations

import numpy as np
import pytest

from assur.groups._rcond import TRUSTED, reciprocal_condition


def _matrices(seed: int, n: int = 400, m: int = 12) -> np.ndarray:
    """Random matrices whose smallest singular value spans 1 to 1e-16."""
    rng = np.random.default_rng(seed)
    u = np.linalg.qr(rng.standard_normal((n, m, m)))[0]
    v = np.linalg.qr(rng.standard_normal((n, m, m)))[0]
    s = np.sort(rng.uniform(0.5, 2.0, (n, m)), axis=-1)[:, ::-1].copy()
    s[:, -1] = 10.0 ** rng.uniform(-16.0, 0.0, n)
    return np.einsum("nij,nj,nkj->nik", u, s, v)


@pytest.mark.parametrize("seed", range(4))
@pytest.mark.parametrize("above", [1e-3, 1e-9, 1e-12])
def test_every_comparison_at_or_below_the_threshold_is_the_exact_ones(seed, above):
    a = _matrices(seed)
    exact = 1.0 / np.linalg.cond(a)
    got = reciprocal_condition(a, above)
    for threshold in (above, above / 10.0, 1e-13):
        assert np.array_equal(got < threshold, exact < threshold)
        assert np.array_equal(got >= threshold, exact >= threshold)
    # below the threshold it is the exact value; above it a lower bound of it
    low = exact < above * 10.0
    assert np.array_equal(got[low & (got < above)], exact[low & (got < above)])
    assert np.all(got <= exact * (1.0 + 1e-12))
    # worse conditioned than the inverse can be trusted, the SVD's value whatever
    # the threshold (near 1e-12 both carry errors of 1e-4)
    poor = exact < TRUSTED
    assert poor.any()
    assert np.array_equal(got[poor], exact[poor])
    # the bound is within the matrices' order of the value (m = 12 here)
    high = got >= above
    assert np.all(got[high] * 12.0 >= exact[high] * (1.0 - 1e-12))


def test_without_a_threshold_it_is_numpys_value():
    a = _matrices(7)
    assert np.array_equal(reciprocal_condition(a), 1.0 / np.linalg.cond(a))


def test_a_singular_matrix_or_one_whose_norms_would_not_hold_gets_numpys_value():
    a = _matrices(3, n=6, m=3)
    a[1] = [[1.0, 2.0, 3.0], [2.0, 4.0, 6.0], [0.0, 0.0, 1.0]]  # exactly singular
    a[3] *= 1e-170  # its squares underflow
    a[4] *= 1e170  # its squares overflow
    with np.errstate(all="ignore"):
        exact = 1.0 / np.linalg.cond(a)
    got = reciprocal_condition(a, 1e-3)
    assert np.array_equal(got, exact)  # the singular one makes the SVD read all
    a[1] = np.eye(3)
    got = reciprocal_condition(a, 1e-3)
    assert got[3] == 1.0 / np.linalg.cond(a[3])
    assert got[4] == 1.0 / np.linalg.cond(a[4])


def test_an_empty_batch():
    assert reciprocal_condition(np.zeros((0, 3, 3)), 1e-3).shape == (0,)
