"""Range-image patches: an offline substitute for the Brown range image database and the pipeline
of Adams & Carlsson (2009), *On the nonlinear statistics of range image patches* (thesis §2.4.3).

The Brown range image database (about 200 laser range scans of outdoor scenes) cannot be downloaded
on this machine, so :func:`synthetic_range_image` renders range images of random scenes with a small
vectorised ray caster: a ground plane, boxes (buildings, crates, randomly oriented rocks), trees
and posts (cylinders, some with round crowns) and clumps of foliage (spheres) at several
distances, seen by a pinhole camera at eye height, with multiplicative range noise for surface
roughness.  Rays that hit nothing within ``max_range`` (the sky) or meet the ground at a grazing
angle are out of range and returned as NaN, as the scanner's missing data.  These images are a
model, not data: results on them say what the pipeline does on such scenes, not what the Brown
scans contain.

The pipeline then follows Adams–Carlsson (after Lee–Pedersen–Mumford 2003):

1. :func:`patches`: ``size × size`` patches (5 × 5 in the thesis) of the *logarithm* of the range,
   patches touching out-of-range pixels are dropped; :func:`sample_patches` draws them at random
   from many images;
2. :func:`contrast_norm`: the D-norm ``‖x‖_D = sqrt(Σ_{i~j} (x_i − x_j)²)`` summed over all pairs of
   4-adjacent pixels (horizontal and vertical neighbours) of the log-range patch;
3. :func:`high_contrast`: keep the fraction ``top`` of patches of largest D-norm (Adams–Carlsson and
   Lee et al. keep the top 20 %);
4. :func:`normalise`: subtract the patch mean and divide by the Euclidean norm, which puts the patches
   on the unit sphere S^{n²−2} of the mean-zero hyperplane (thesis: "mapped to the unit sphere by
   dividing each vector by its Euclidean norm");
5. :func:`density_filter`: X(k, percent), the ``percent`` % of points with the smallest distance to
   their k-th nearest neighbour (the thesis's X⁵(300, 30));
6. :func:`dct_basis` and :func:`gradient_projection`: coordinates in the orthonormal 2-D DCT-II basis
   and the projection onto its two linear-gradient vectors (horizontal and vertical, Figure 2.23).
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import numpy.typing as npt

from .._validate import check_int, check_real, check_seed

__all__ = [
    "synthetic_range_image",
    "patches",
    "sample_patches",
    "contrast_norm",
    "high_contrast",
    "normalise",
    "density_filter",
    "kth_neighbour_distance",
    "dct_basis",
    "dct_basis_5x5",
    "gradient_projection",
    "dct_gradient_correlation",
    "projection_summary",
    "range_patch_space",
]


# =========================================================================== ray caster
def _hit_plane_y(orig, dirs, height):
    """Distance along each ray to the horizontal plane y = height (inf when missed)."""
    dy = dirs[:, 1]
    with np.errstate(divide="ignore", invalid="ignore"):
        t = (height - orig[1]) / dy
    return np.where(t > 1e-9, t, np.inf)


def _hit_sphere(orig, dirs, centre, radius):
    oc = orig - centre
    b = dirs @ oc
    c = oc @ oc - radius**2
    disc = b * b - c
    root = np.sqrt(np.maximum(disc, 0.0))
    t0, t1 = -b - root, -b + root
    t = np.where(t0 > 1e-9, t0, np.where(t1 > 1e-9, t1, np.inf))
    return np.where(disc >= 0, t, np.inf)


def _hit_box(orig, dirs, centre, half, rot):
    """Slab test for an oriented box; ``rot`` maps box coordinates to world coordinates."""
    o = (orig - centre) @ rot
    d = dirs @ rot
    with np.errstate(divide="ignore", invalid="ignore"):
        inv = 1.0 / d
        t1 = (-half - o) * inv
        t2 = (half - o) * inv
    t1 = np.where(np.isnan(t1), -np.inf, t1)
    t2 = np.where(np.isnan(t2), np.inf, t2)
    tnear = np.max(np.minimum(t1, t2), axis=1)
    tfar = np.min(np.maximum(t1, t2), axis=1)
    t = np.where(tnear > 1e-9, tnear, tfar)
    return np.where((tfar >= tnear) & (tfar > 1e-9), t, np.inf)


def _hit_cylinder(orig, dirs, base, radius, height):
    """Upright (y-axis) cylinder of given radius from y = base[1] to base[1] + height, with a lid."""
    ox, oz = orig[0] - base[0], orig[2] - base[2]
    dx, dz = dirs[:, 0], dirs[:, 2]
    a = dx * dx + dz * dz
    b = ox * dx + oz * dz
    c = ox * ox + oz * oz - radius**2
    disc = b * b - a * c
    root = np.sqrt(np.maximum(disc, 0.0))
    with np.errstate(divide="ignore", invalid="ignore"):
        t0 = (-b - root) / a
        t1 = (-b + root) / a
    out = np.full(dirs.shape[0], np.inf)
    for t in (t1, t0):  # t0 last: the nearer wall wins
        y = orig[1] + t * dirs[:, 1]
        ok = (disc >= 0) & (a > 1e-15) & (t > 1e-9) & (y >= base[1]) & (y <= base[1] + height)
        out = np.where(ok & (t < out), t, out)
    tl = _hit_plane_y(orig, dirs, base[1] + height)
    px = orig[0] + tl * dirs[:, 0] - base[0]
    pz = orig[2] + tl * dirs[:, 2] - base[2]
    lid = np.isfinite(tl) & (px * px + pz * pz <= radius**2)
    return np.where(lid & (tl < out), tl, out)


def _rotation(yaw, pitch=0.0, roll=0.0):
    cy, sy = np.cos(yaw), np.sin(yaw)
    cp, sp = np.cos(pitch), np.sin(pitch)
    cr, sr = np.cos(roll), np.sin(roll)
    ry = np.array([[cy, 0, sy], [0, 1, 0], [-sy, 0, cy]])
    rx = np.array([[1, 0, 0], [0, cp, -sp], [0, sp, cp]])
    rz = np.array([[cr, -sr, 0], [sr, cr, 0], [0, 0, 1]])
    return ry @ rx @ rz


def synthetic_range_image(
    *,
    seed: int,
    size: tuple[int, int] = (192, 256),
    n_boxes: int = 2,
    n_cylinders: int = 4,
    n_spheres: int = 70,
    n_rocks: int = 15,
    fov_degrees: float = 46.0,
    camera_height: float = 1.6,
    max_range: float = 60.0,
    noise: float = 0.03,
    min_grazing_degrees: float = 4.0,
) -> np.ndarray:
    """Range image (distance from the camera, in metres) of a random scene, NaN where out of range.

    Thesis: §2.4.3, Figure 2.21 (a range image; here a synthetic substitute for the Brown database).

    The scene has a ground plane y = 0, ``n_boxes`` boxes (buildings, walls, tilted crates),
    ``n_cylinders`` upright cylinders (posts, or tree trunks carrying a round crown), ``n_spheres``
    spheres (bushes, boulders, clumps of foliage up to 7 m high) and ``n_rocks`` boxes in uniformly
    random 3-D orientations partly sunk into the ground, placed between 3 and 40 m in front of a
    pinhole camera at ``camera_height`` with a random small yaw and pitch.  ``noise`` is the
    relative standard deviation of multiplicative Gaussian range noise.  Like a laser scanner, the
    camera gets no return from the ground at grazing incidence: rays that meet the ground at less
    than ``min_grazing_degrees`` are out of range.

    The defaults describe a cluttered, mostly vegetated outdoor scene (many clumps of foliage, a few
    trees, posts, buildings and rocks) at a fine angular resolution (46° over 256 columns, 0.18° per
    pixel) with 3 % range noise standing in for surface roughness (grass, bark, leaves).  Without
    that roughness the smooth ground and surfaces give dense clusters of near-linear gradients that
    dominate the high-contrast patches; the experiment ``range-patches`` records this sensitivity.

    Parameters
    ----------
    seed : int
        Seed of the random scene, camera and noise.
    size : tuple of int
        ``(height, width)`` in pixels.
    n_boxes, n_cylinders, n_spheres, n_rocks : int
        How many objects of each kind (>= 0).
    fov_degrees : float
        Horizontal field of view, in (0, 170).
    camera_height : float
        Height of the camera above the ground (m), > 0.
    max_range : float
        The scanner's range (m), > 0: farther hits are out of range.
    noise : float
        Relative standard deviation of the multiplicative range noise, >= 0.
    min_grazing_degrees : float
        Smallest angle of incidence on the ground that gives a return, in [0, 90).

    Returns
    -------
    numpy.ndarray of float64, shape (height, width)
        Distances (m); NaN for out-of-range pixels.  Row 0 is the top of the picture.

    Raises
    ------
    ValueError
        Any argument outside the ranges above.
    """
    h, w = _check_size(size)
    counts = (("n_boxes", n_boxes), ("n_cylinders", n_cylinders), ("n_spheres", n_spheres), ("n_rocks", n_rocks))
    for name, value in counts:
        check_int(value, name, minimum=0)
    if not (0 < fov_degrees < 170):
        raise ValueError(f"fov_degrees must lie in (0, 170), got {fov_degrees!r}")
    check_real(camera_height, "camera_height", positive=True)
    check_real(max_range, "max_range", positive=True)
    if not (np.isfinite(min_grazing_degrees) and 0 <= min_grazing_degrees < 90):
        raise ValueError(f"min_grazing_degrees must lie in [0, 90), got {min_grazing_degrees!r}")
    check_real(noise, "noise", minimum=0.0)
    rng = np.random.default_rng(check_seed(seed))

    # Camera: looks along +z, x to the right, y up; image row 0 is the top.
    cam_rot = _rotation(rng.uniform(-0.3, 0.3), rng.uniform(-0.12, 0.05))
    focal = 0.5 * w / np.tan(np.radians(fov_degrees) / 2)
    u = (np.arange(w) - (w - 1) / 2) / focal
    v = -(np.arange(h) - (h - 1) / 2) / focal
    uu, vv = np.meshgrid(u, v)
    dirs = np.stack([uu.ravel(), vv.ravel(), np.ones(h * w)], axis=1)
    dirs /= np.linalg.norm(dirs, axis=1, keepdims=True)
    dirs = dirs @ cam_rot.T
    orig = np.array([0.0, camera_height, 0.0])

    def place(near, far, spread):
        z = rng.uniform(near, far)
        return np.array([rng.uniform(-spread, spread) * z / 10 + 0.0, 0.0, z])

    t = _hit_plane_y(orig, dirs, 0.0)
    t = np.where(-dirs[:, 1] >= np.sin(np.radians(min_grazing_degrees)), t, np.inf)

    def add(hit, bound_centre, bound_radius, *args):
        """Intersect only the rays that meet the object's bounding sphere; keep the nearest hit."""
        oc = bound_centre - orig
        proj = dirs @ oc
        perp2 = oc @ oc - proj * proj
        idx = np.flatnonzero((perp2 <= bound_radius**2) & (proj > -bound_radius))
        if idx.size:
            t[idx] = np.minimum(t[idx], hit(orig, dirs[idx], *args))

    for _ in range(n_boxes):
        c = place(5.0, 40.0, 6.0)
        half = rng.uniform([0.3, 0.3, 0.3], [4.0, 3.0, 2.0])
        tilted = rng.random() < 0.4
        rot = _rotation(rng.uniform(0, np.pi), *(rng.uniform(-0.6, 0.6, 2) if tilted else (0.0, 0.0)))
        c[1] = half[1] if not tilted else half.max() * 0.8
        add(_hit_box, c, np.linalg.norm(half), c, half, rot)
    for _ in range(n_rocks):
        c = place(3.0, 30.0, 5.0)
        half = rng.uniform(0.2, 1.2, 3)
        q, r = np.linalg.qr(rng.standard_normal((3, 3)))
        rot = q * np.sign(np.diag(r))  # a uniformly random orthogonal matrix
        c[1] = rng.uniform(0.0, 0.6) * half.min()
        add(_hit_box, c, np.linalg.norm(half), c, half, rot)
    for _ in range(n_cylinders):
        c = place(3.0, 30.0, 5.0)
        height = rng.uniform(1.0, 8.0)
        radius = rng.uniform(0.1, 0.6)
        add(_hit_cylinder, c + np.array([0.0, height / 2, 0.0]), np.hypot(radius, height / 2), c, radius, height)
        if rng.random() < 0.6:  # a tree: a round crown on the trunk
            crown = rng.uniform(1.0, 3.0)
            top = c + np.array([0.0, height + 0.7 * crown, 0.0])
            add(_hit_sphere, top, crown, top, crown)
    for _ in range(n_spheres):
        c = place(3.0, 30.0, 5.0)
        r = rng.uniform(0.3, 1.5)
        c[1] = rng.uniform(0.6 * r, max(0.6 * r, 7.0))  # bushes on the ground up to foliage clumps in the air
        add(_hit_sphere, c, r, c, r)
    if noise > 0:
        t = t * (1.0 + noise * rng.standard_normal(t.shape))
    t = np.where((t <= max_range) & (t > 0), t, np.nan)
    return t.reshape(h, w)


def _check_size(size) -> tuple[int, int]:
    try:
        h, w = (int(s) for s in size)
    except (TypeError, ValueError):
        raise ValueError(f"size must be a pair (height, width), got {size!r}") from None
    if h < 1 or w < 1 or (h, w) != tuple(size):
        raise ValueError(f"size must be two positive integers, got {size!r}")
    return h, w


# =========================================================================== patches
def patches(image: npt.ArrayLike, *, size: int = 5, log: bool = True) -> np.ndarray:
    """All ``size × size`` patches of a range image as rows of length size² (row-major pixels).

    Thesis: §2.4.3 (5 × 5 patches thought of as vectors in R^25; Adams–Carlsson 2009 use the
    logarithm of the range).  Patches touching a NaN (out-of-range) or non-positive pixel are dropped.

    Parameters
    ----------
    image : array_like, shape (h, w)
        A range image, NaN where out of range (no infinite values).
    size : int
        The patch side, >= 2 (5 in the thesis).
    log : bool
        Use the logarithm of the range (Adams–Carlsson) instead of the range itself.

    Returns
    -------
    numpy.ndarray of float64, shape (m, size²)
        The valid patches, by their top-left corner in row-major order.

    Raises
    ------
    ValueError
        An image that is not 2-D, smaller than a patch or has infinite values; a bad ``size``.
    """
    size = _check_patch_size(size)
    img, valid = _valid_windows(image, size, log)
    win = np.lib.stride_tricks.sliding_window_view(img, (size, size))
    return np.ascontiguousarray(win[valid].reshape(-1, size * size))


def _valid_windows(image: np.ndarray, size: int, log: bool) -> tuple[np.ndarray, np.ndarray]:
    """The image as used for patches (log range or raw) and the mask of valid top-left corners."""
    img = np.asarray(image, dtype=np.float64)
    if img.ndim != 2:
        raise ValueError(f"a range image is a 2-D array, got shape {img.shape}")
    if img.shape[0] < size or img.shape[1] < size:
        raise ValueError(f"image of shape {img.shape} is smaller than a {size}x{size} patch")
    if np.any(np.isinf(img)):
        raise ValueError("range image has infinite values; mark out-of-range pixels with NaN")
    if log:
        with np.errstate(invalid="ignore", divide="ignore"):
            img = np.where(img > 0, np.log(np.where(img > 0, img, 1.0)), np.nan)
    bad = (~np.isfinite(img)).astype(np.int64)
    # number of bad pixels in every size x size window, from a summed-area table
    sat = np.pad(bad.cumsum(0).cumsum(1), ((1, 0), (1, 0)))
    count = sat[size:, size:] - sat[:-size, size:] - sat[size:, :-size] + sat[:-size, :-size]
    return img, count == 0


def sample_patches(images: Sequence[npt.ArrayLike], *, n: int, size: int = 5, seed: int = 0,
                   log: bool = True) -> np.ndarray:
    """``n`` patches drawn uniformly without replacement from the valid patches of all ``images``.

    Thesis: §2.4.3 (4·10⁵ random 5 × 5 patches from about 200 range images).  The same rows, in
    the same order, as drawing ``n`` rows from the concatenated :func:`patches` of the images.

    Parameters
    ----------
    images : sequence of array_like
        Range images (as for :func:`patches`).
    n : int
        The number of patches, at most the number of valid ones.
    size : int
        The patch side, >= 2 (5 in the thesis).
    seed : int
        Seed of the draw.
    log : bool
        Use the logarithm of the range (Adams–Carlsson) instead of the range itself.

    Returns
    -------
    numpy.ndarray of float64, shape (n, size²)
        The drawn patches, ordered by image and then by top-left corner.

    Raises
    ------
    ValueError
        ``n`` not a positive integer or larger than the number of valid patches, no images, or an
        invalid image or ``size``.
    """
    n = check_int(n, "n", minimum=1)
    if len(images) == 0:
        raise ValueError("no images given")
    size = _check_patch_size(size)
    prepared = [_valid_windows(im, size, log) for im in images]
    corners = [np.flatnonzero(valid) for _, valid in prepared]
    offsets = np.cumsum([0] + [c.size for c in corners])
    total = int(offsets[-1])
    if n > total:
        raise ValueError(f"asked for {n} patches, the images have only {total} valid ones")
    chosen = np.sort(np.random.default_rng(check_seed(seed)).choice(total, size=n, replace=False))
    which = np.searchsorted(offsets, chosen, side="right") - 1
    out = np.empty((n, size * size))
    dr, dc = np.divmod(np.arange(size * size), size)
    for i, (img, valid) in enumerate(prepared):
        rows = chosen[which == i] - offsets[i]
        if rows.size == 0:
            continue
        r, c = np.divmod(corners[i][rows], valid.shape[1])
        out[which == i] = img[r[:, None] + dr, c[:, None] + dc]
    return out


def _check_patch_size(size) -> int:
    size = check_int(size, "patch size", minimum=2)
    return int(size)


def _as_patch_rows(X) -> tuple[np.ndarray, int]:
    arr = np.asarray(X, dtype=np.float64)
    if arr.ndim != 2 or arr.shape[0] == 0:
        raise ValueError(f"patches must be a non-empty (n, size²) array, got shape {arr.shape}")
    size = int(round(np.sqrt(arr.shape[1])))
    if size * size != arr.shape[1] or size < 2:
        raise ValueError(f"patch length {arr.shape[1]} is not a square >= 4")
    if not np.all(np.isfinite(arr)):
        raise ValueError("patches contain NaN or infinite values")
    return arr, size


def contrast_norm(X: npt.ArrayLike) -> np.ndarray:
    """D-norm of each patch: sqrt of the sum of squared differences of 4-adjacent pixels.

    Thesis: §2.4.3 ("a notion of contrast"); the D-norm of Lee–Pedersen–Mumford (2003) used by
    Adams–Carlsson (2009), ``‖x‖_D² = Σ_{i~j} (x_i − x_j)² = xᵀ D x`` with D the graph Laplacian of
    the patch's 4-neighbour grid.

    Parameters
    ----------
    X : array_like, shape (n, size²)
        Finite patches as rows (row-major pixels), n >= 1, size >= 2.

    Returns
    -------
    numpy.ndarray of float64, shape (n,)
        The D-norm of each patch.

    Raises
    ------
    ValueError
        Patches that are not a non-empty finite ``(n, size²)`` array.
    """
    arr, size = _as_patch_rows(X)
    p = arr.reshape(-1, size, size)
    dh = np.diff(p, axis=2)
    dv = np.diff(p, axis=1)
    return np.sqrt(np.sum(dh * dh, axis=(1, 2)) + np.sum(dv * dv, axis=(1, 2)))


def high_contrast(X: npt.ArrayLike, *, top: float = 0.2) -> np.ndarray:
    """The fraction ``top`` of patches with the largest D-norm (ties broken by position).

    Thesis: §2.4.3 (high-contrast patches; Adams–Carlsson keep the top 20 %).

    Parameters
    ----------
    X : array_like, shape (n, size²)
        Patches as for :func:`contrast_norm`.
    top : float
        The fraction kept, in (0, 1]; at least one patch is kept.

    Returns
    -------
    numpy.ndarray of float64, shape (round(top · n), size²)
        The kept patches, in their input order.

    Raises
    ------
    ValueError
        Bad patches (as :func:`contrast_norm`), or a ``top`` outside (0, 1].
    """
    arr, _ = _as_patch_rows(X)
    if not (0 < top <= 1):
        raise ValueError(f"top must be a fraction in (0, 1], got {top!r}")
    m = max(1, int(round(top * arr.shape[0])))
    order = np.argsort(-contrast_norm(arr), kind="stable")[:m]
    return arr[np.sort(order)]


def normalise(X: npt.ArrayLike) -> np.ndarray:
    """Subtract each patch's mean and divide by its Euclidean norm (points on the unit sphere).

    Thesis: §2.4.3 ("mapped to the unit sphere by dividing each vector by its Euclidean norm").

    Parameters
    ----------
    X : array_like, shape (n, size²)
        Patches as rows, none of them constant.

    Returns
    -------
    numpy.ndarray of float64, shape (n, size²)
        Mean-zero rows of Euclidean norm 1.

    Raises
    ------
    ValueError
        Bad patches (as :func:`contrast_norm`), or a constant patch (it has no direction).
    """
    arr, _ = _as_patch_rows(X)
    centred = arr - arr.mean(axis=1, keepdims=True)
    norms = np.linalg.norm(centred, axis=1, keepdims=True)
    scale = np.abs(arr).max(axis=1, keepdims=True) + 1.0
    if np.any(norms <= 1e-12 * scale):
        raise ValueError("a constant patch has no direction; drop low-contrast patches first")
    return centred / norms


# =========================================================================== density
def kth_neighbour_distance(X: npt.ArrayLike, *, k: int) -> np.ndarray:
    """ρ_k(x): the distance from each point to its k-th nearest other point.

    Thesis: §2.4.3 (density is determined by the distance to the k-th closest neighbour).

    Parameters
    ----------
    X : array_like, shape (n, d)
        Finite points, n >= 1.
    k : int
        Which neighbour, ``1 <= k < n`` (the point itself is not counted).

    Returns
    -------
    numpy.ndarray of float64, shape (n,)
        ρ_k of each point.

    Raises
    ------
    ValueError
        Points that are not a non-empty finite ``(n, d)`` array, or a bad ``k``.
    """
    from scipy.spatial import cKDTree

    arr = np.asarray(X, dtype=np.float64)
    if arr.ndim != 2 or arr.shape[0] == 0:
        raise ValueError(f"points must be a non-empty (n, d) array, got shape {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise ValueError("points contain NaN or infinite values")
    k = check_int(k, "k", minimum=1)
    if k >= arr.shape[0]:
        raise ValueError(f"k = {k} needs more than {k} points, got {arr.shape[0]}")
    k = int(k)
    if arr.shape[1] <= 8:
        dist, _ = cKDTree(arr).query(arr, k=[k + 1])  # the first neighbour is the point itself
        return dist[:, 0]
    # High dimension (25 for 5 x 5 patches): k-d trees degrade, blocks of a Gram matrix do not.
    n = arr.shape[0]
    sq = np.einsum("ij,ij->i", arr, arr)
    out = np.empty(n)
    step = max(1, min(n, 2**23 // max(n, 1)))
    for start in range(0, n, step):
        stop = min(n, start + step)
        d2 = sq[start:stop, None] + sq[None, :] - 2.0 * (arr[start:stop] @ arr.T)
        d2[np.arange(stop - start), np.arange(start, stop)] = -np.inf  # the point itself comes first
        j = np.argpartition(d2, k, axis=1)[:, k]
        out[start:stop] = np.linalg.norm(arr[start:stop] - arr[j], axis=1)  # exact distance
    return out


def _check_percent(percent) -> float:
    """``percent`` as a float, a percentage in (0, 100]."""
    if isinstance(percent, bool) or not isinstance(percent, (int, float, np.integer, np.floating)) \
            or not (0 < percent <= 100):
        raise ValueError(f"percent is a percentage in (0, 100], got {percent!r}")
    return float(percent)


def density_filter(
    X: npt.ArrayLike, *, k: int, percent: float, return_index: bool = False
) -> np.ndarray | tuple[np.ndarray, np.ndarray]:
    """X(k, percent): the ``percent`` % of points with the smallest distance to their k-th nearest neighbour.

    Thesis: §2.4.3 (the top 30 % densest points by the 300th neighbour give X⁵(300, 30)).
    Ties are broken by position; indices are returned in increasing order.

    Parameters
    ----------
    X : array_like, shape (n, d)
        Finite points.
    k : int
        The neighbour whose distance measures density (the point itself is not counted), ``k < n``.
    percent : float
        The percentage of points kept, in (0, 100].
    return_index : bool
        Also return the indices of the kept points.

    Returns
    -------
    kept : numpy.ndarray of float64, shape (round(percent / 100 · n), d)
        The kept points (at least one), in their input order.
    index : numpy.ndarray of int
        Their row numbers in ``X``, increasing (only if ``return_index``).

    Raises
    ------
    ValueError
        A ``percent`` outside (0, 100], or as :func:`kth_neighbour_distance`.
    """
    percent = _check_percent(percent)
    rho = kth_neighbour_distance(X, k=k)
    m = max(1, int(round(percent / 100 * rho.shape[0])))
    idx = np.sort(np.argsort(rho, kind="stable")[:m])
    out = np.asarray(X, dtype=np.float64)[idx]
    return (out, idx) if return_index else out


# =========================================================================== DCT
def dct_basis(*, size: int = 5) -> np.ndarray:
    """Orthonormal 2-D DCT-II basis of size × size patches: row ``i*size + j`` is c_i ⊗ c_j.

    Thesis: §2.4.3 (normalised discrete cosine transform, Figure 2.23).  ``c_k(m) =
    a_k cos(π (2m + 1) k / (2 size))`` with a_0 = sqrt(1/size), a_k = sqrt(2/size); c_i varies down
    the rows of the patch and c_j along the columns.  Row 0 is the constant patch.

    Parameters
    ----------
    size : int
        The patch side, >= 2.

    Returns
    -------
    numpy.ndarray of float64, shape (size², size²)
        An orthogonal matrix whose rows are the basis vectors (row-major pixels).

    Raises
    ------
    ValueError
        If ``size`` is not an integer >= 2.
    """
    size = _check_patch_size(size)
    m = np.arange(size)
    k = np.arange(size)[:, None]
    c = np.cos(np.pi * (2 * m[None, :] + 1) * k / (2 * size))
    c *= np.where(k == 0, np.sqrt(1.0 / size), np.sqrt(2.0 / size))
    return np.einsum("ia,jb->ijab", c, c).reshape(size * size, size * size)


def dct_basis_5x5() -> np.ndarray:
    """The 25 orthonormal DCT basis vectors of 5 × 5 patches (rows), as :func:`dct_basis`.

    Thesis: §2.4.3, Figure 2.23.

    Returns
    -------
    numpy.ndarray of float64, shape (25, 25)
        ``dct_basis(size=5)``.
    """
    return dct_basis(size=5)


def gradient_projection(X: npt.ArrayLike) -> np.ndarray:
    """Coordinates of patches on the two linear-gradient DCT vectors: (horizontal, vertical).

    Thesis: §2.4.3, Figure 2.23 (projection onto the horizontal and vertical gradients).
    Column 0 uses the vector c_0 ⊗ c_1 (varies along a row: a horizontal gradient), column 1 uses
    c_1 ⊗ c_0 (varies down a column: a vertical gradient).  For unit patches both lie in [−1, 1].

    Parameters
    ----------
    X : array_like, shape (n, size²)
        Patches as rows; unit ones (:func:`normalise`) give coordinates in [−1, 1].

    Returns
    -------
    numpy.ndarray of float64, shape (n, 2)
        (horizontal, vertical) coordinates of each patch.
    """
    arr, size = _as_patch_rows(X)
    basis = dct_basis(size=size)
    return arr @ basis[[1, size]].T


def dct_gradient_correlation(*, size: int = 5) -> float:
    """How close the two DCT gradient vectors are to linear ramps: the smaller |correlation| of the two.

    Thesis: §2.4.3, Figure 2.23 (the DCT vectors c_0 ⊗ c_1 and c_1 ⊗ c_0 as the horizontal and
    vertical gradients).  The ramp rises by one per pixel along each row (for c_0 ⊗ c_1) or down
    each column (for c_1 ⊗ c_0); the basis rows have norm 1.

    Parameters
    ----------
    size : int
        The patch side, >= 2.

    Returns
    -------
    float
        ``min |⟨c, r⟩| / ‖r‖`` over the two pairs (vector, ramp): 1 for a vector that is a ramp.

    Raises
    ------
    ValueError
        If ``size`` is not an integer >= 2.

    Examples
    --------
    >>> round(dct_gradient_correlation(size=5), 4)
    0.996
    """
    size = _check_patch_size(size)
    basis = dct_basis(size=size)
    ramp = np.tile(np.arange(size) - (size - 1) / 2, (size, 1))  # rises along each row
    return min(abs(float(basis[row] @ r.ravel())) / float(np.linalg.norm(r))
               for row, r in ((1, ramp), (size, ramp.T)))


def projection_summary(coords: npt.ArrayLike, *, n_sectors: int = 12) -> dict[str, float | int]:
    """Whether projected patches lie on a circle: distance from the origin, and the directions they fill.

    Thesis: §2.4.3, Figure 2.23 (the projection onto the two gradients shows a circle: the primary
    circle of Adams–Carlsson).

    Parameters
    ----------
    coords : array_like, shape (n, 2)
        Projected patches (:func:`gradient_projection`).
    n_sectors : int, default 12
        The number of equal sectors of directions counted.

    Returns
    -------
    dict
        ``radius_median`` (median distance from the origin), ``sectors_held`` (sectors holding a
        point), ``angle_coverage`` (their fraction) and ``inner_fraction`` (the fraction of points
        within half the median distance: near 0 for a circle, larger for a disc).

    Raises
    ------
    ValueError
        ``coords`` not a non-empty (n, 2) array of finite numbers, or ``n_sectors`` below 1.

    Examples
    --------
    >>> t = np.linspace(0, 2 * np.pi, 100, endpoint=False)
    >>> summary = projection_summary(np.column_stack([np.cos(t), np.sin(t)]))
    >>> summary["sectors_held"], summary["inner_fraction"]
    (12, 0.0)
    """
    c = np.asarray(coords, dtype=np.float64)
    if c.ndim != 2 or c.shape[1] != 2 or c.shape[0] == 0 or not np.all(np.isfinite(c)):
        raise ValueError(f"coords must be a non-empty (n, 2) array of finite numbers, got shape {c.shape}")
    n_sectors = check_int(n_sectors, "n_sectors", minimum=1)
    radius = np.linalg.norm(c, axis=1)
    angles = np.arctan2(c[:, 1], c[:, 0])
    sectors = np.histogram(angles, bins=int(n_sectors), range=(-np.pi, np.pi))[0] > 0
    return {"radius_median": float(np.median(radius)), "sectors_held": int(sectors.sum()),
            "angle_coverage": float(np.mean(sectors)),
            "inner_fraction": float(np.mean(radius < 0.5 * np.median(radius)))}


# =========================================================================== pipeline
def range_patch_space(
    images: Sequence[npt.ArrayLike],
    *,
    n_patches: int,
    k: int = 300,
    percent: float = 30.0,
    size: int = 5,
    top: float = 0.2,
    seed: int = 0,
) -> dict[str, np.ndarray]:
    """The whole pipeline of Adams–Carlsson: sample, log range, keep high contrast, normalise, X(k, percent).

    Thesis: §2.4.3 (the point set X⁵(300, 30) of Figure 2.22).

    Parameters
    ----------
    images : sequence of array_like
        Range images, NaN where out of range.
    n_patches : int
        The number of patches sampled (:func:`sample_patches`).
    k : int
        The density neighbour (:func:`density_filter`).
    percent : float
        The percentage of densest patches kept (30: the thesis's X⁵(300, 30)).
    size : int
        The patch side.
    top : float
        The fraction of highest-contrast patches kept (:func:`high_contrast`).
    seed : int
        Seed of the patch sample.

    Returns
    -------
    dict of str to numpy.ndarray
        ``patches`` (the sampled log-range patches), ``high`` (the normalised high-contrast
        patches, on the unit sphere) and ``dense`` (X(k, percent)).

    Raises
    ------
    ValueError
        As the steps above.
    """
    percent = _check_percent(percent)
    raw = sample_patches(images, n=n_patches, size=size, seed=seed)
    high = normalise(high_contrast(raw, top=top))
    dense = density_filter(high, k=k, percent=percent)
    return {"patches": raw, "high": high, "dense": dense}
