"""The tests' own NURBS evaluator (Cox–de Boor recursion on homogeneous coordinates),
independent of the library's: exported NURBS data are checked against it."""

import numpy as np


def basis(knots, degree, t):
    """The degree-p B-spline basis functions N_{i,p}(t), all of them, at t (right end
    included in the last span)."""
    knots = np.asarray(knots, dtype=float)
    n = len(knots) - degree - 1
    if t >= knots[-1]:
        span = np.searchsorted(knots, knots[-1], side="left") - 1
    else:
        span = np.searchsorted(knots, t, side="right") - 1
    N = np.zeros(len(knots) - 1)
    N[span] = 1.0
    for p in range(1, degree + 1):
        nxt = np.zeros(len(knots) - 1 - p)
        for i in range(len(nxt)):
            a = knots[i + p] - knots[i]
            b = knots[i + p + 1] - knots[i + 1]
            left = (t - knots[i]) / a * N[i] if a > 0 else 0.0
            right = (knots[i + p + 1] - t) / b * N[i + 1] if b > 0 else 0.0
            nxt[i] = left + right
        N = nxt
    return N[:n]


def curve_point(degree, poles, weights, knots, t):
    N = basis(knots, degree, t) * weights
    return N @ poles / N.sum()


def surface_point(degree_u, degree_v, poles, weights, knots_u, knots_v, u, v):
    Nu = basis(knots_u, degree_u, u)
    Nv = basis(knots_v, degree_v, v)
    W = np.outer(Nu, Nv) * weights
    return np.einsum("ij,ijk->k", W, poles) / W.sum()
