"""refine(min_angle=) on random thin-layer domains (the case quality refinement finds hardest): layers between
wavy interfaces, each curve sampled at its own spacing. Angles and region areas are recomputed here from the
mesh; both sides of every boundary and interface edge are checked by the exact rational oracle."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

import nonobtuse
from nonobtuse import Domain
from refine_helpers import obtuse_constraint_sides
from test_quality2d import areas, smallest_angles


def layers(seed: int, n_layers: int, thickness: float) -> tuple[Domain, np.ndarray]:
    """A 100-long stack of n_layers layers, each about `thickness` thick, between gently wavy curves sampled
    at 4-12 points each (so every input angle is near 90 degrees: none below 60), one region seed per layer
    (attribute = layer number). Also returns the area of every layer (shoelace on its polygon)."""
    rng = np.random.default_rng(seed)
    curves = []
    for k in range(n_layers + 1):
        x = np.r_[0.0, np.sort(rng.uniform(5, 95, int(rng.integers(2, 11)))), 100.0]
        amplitude, phase = rng.uniform(0, 0.2 * thickness), rng.uniform(0, 2 * np.pi)
        curves.append(np.c_[x, k * thickness + amplitude * np.sin(2 * np.pi * x / 100 + phase)])
    first = np.cumsum([0] + [len(c) for c in curves])
    segments = [np.c_[np.arange(s, e - 1), np.arange(s + 1, e)] for s, e in zip(first, first[1:])]
    left, right = first[:-1], first[1:] - 1
    segments += [np.c_[left[:-1], left[1:]], np.c_[right[:-1], right[1:]]]
    regions, layer_areas = [], []
    for k in range(n_layers):
        lo, hi = curves[k], curves[k + 1]
        ring = np.r_[lo, hi[::-1]]
        x, y = ring[:, 0], ring[:, 1]
        layer_areas.append(0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1))))
        regions.append((50.0, 0.5 * (np.interp(50, *lo.T) + np.interp(50, *hi.T)), k + 1.0))
    d = Domain(points=np.vstack(curves), segments=np.vstack(segments), regions=regions)
    return d, np.array(layer_areas)


@settings(max_examples=12, deadline=30000, derandomize=True)
@given(seed=st.integers(0, 2**32 - 1), n_layers=st.integers(1, 3),
       thickness=st.sampled_from([1.0, 3.0, 10.0]), min_angle=st.sampled_from([25.0, 30.0]))
def test_thin_layers_reach_the_bound_certified(seed: int, n_layers: int, thickness: float,
                                               min_angle: float) -> None:
    d, layer_areas = layers(seed, n_layers, thickness)
    res = nonobtuse.refine(d, min_angle=min_angle)
    assert res.status == "converged"
    assert obtuse_constraint_sides(res.mesh) == 0  # both sides of every interface, exactly
    assert smallest_angles(res.mesh).min() >= min_angle - 1e-9
    a, region = areas(res.mesh), np.asarray(res.mesh.regions)
    for k, area in enumerate(layer_areas):
        assert abs(a[region == k + 1.0].sum() - area) <= 1e-9 * area  # each layer covered, nothing else
    q = res.stats["quality"]
    assert q["small_angle_triangles"] == 0 and q["bad_triangles"] == 0
    assert res.stats["steiner_points"] + res.stats["interior_points"] == len(res.mesh.points) - len(d.points)
