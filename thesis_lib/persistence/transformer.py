"""Persistence diagrams of many point clouds, in scikit-learn's estimator style.

:class:`RipsDiagrams` is a stateless transformer: ``fit`` checks the parameters, ``transform`` maps
a list of point clouds to their Vietoris–Rips persistence diagrams (the implicit engine of
:func:`~thesis_lib.persistence.rips_persistence`, with the parameters parsed once for all the
clouds).  It has ``get_params``/``set_params`` like any scikit-learn estimator, so
``sklearn.base.clone``, ``Pipeline`` and grid searches accept it, but scikit-learn is not needed to
use it.  Diagrams are in the ripser/persim format (one ``(m, 2)`` array per dimension) with this
library's values, ε, half the diameter, or with ``scale="diameter"`` ripser's and giotto-ph's 2ε;
``homology_dimensions`` chooses the dimensions as giotto-ph's ``VietorisRipsPersistence`` does,
``output="padded"`` gives giotto-tda's padded array of triples, and ``n_jobs`` computes the clouds in
parallel threads (the engine releases the interpreter while it works).
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from concurrent.futures import ThreadPoolExecutor
from typing import Any

import numpy as np
import numpy.typing as npt

from .._validate import (
    MAX_DIM,
    Field,
    InvalidTypeError,
    check_choice,
    check_int,
    check_max_dim,
    check_min_persistence,
    check_radius,
    check_scale,
    parse_field,
    parse_points,
    parse_rips_input,
)
from .implicit import rips_barcode

__all__ = ["RipsDiagrams", "OUTPUTS", "METRICS"]

#: the layouts of :meth:`RipsDiagrams.transform`: a list of arrays per cloud, or giotto-tda's padded array
OUTPUTS = ("list", "padded")
#: what each item of ``X`` is: a point cloud (Euclidean distances) or a distance matrix, as giotto-ph's ``metric``
METRICS = ("euclidean", "precomputed")


class RipsDiagrams:
    """Point clouds → Vietoris–Rips persistence diagrams, as a scikit-learn-style transformer.

    Thesis: Definition 2.11 (the Rips filtration) and Definition 2.34 (its P-intervals, drawn as
    points of a diagram).

    Parameters
    ----------
    max_radius : float, default inf
        Scale ε: a simplex enters when its diameter is at most 2ε.
    max_dim : int, default 2
        Largest simplex dimension built; diagrams of dimensions 0 .. max_dim − 1 are returned (the
        complete ones).
    coefficients : int, default 2
        A prime p: homology over Z/p.
    homology_dimensions : iterable of int, optional
        The homology dimensions computed and returned, as giotto-ph's (e.g. ``(0, 1)``, or ``(1,)``
        alone); the complex is then built up to ``max_dim = max(homology_dimensions) + 1`` (a
        ``max_dim`` other than its default that disagrees is refused).  None: 0 .. max_dim − 1.
    scale : {"epsilon", "radius", "diameter"}, default "epsilon"
        The values of the diagrams: ε (the thesis's; "radius" is the same), or ``"diameter"``, 2ε,
        ripser.py's and giotto-ph's (as :meth:`Barcode.to_diagrams`).
    min_persistence : float, default 0.0
        Points with ``death − birth <= min_persistence`` (in the values returned, after ``scale``)
        are left out; 0: only the zero-length ones.  1e-12 drops the bars of length ~1e-16 that
        tied distances give (ripser.py, on float32 distances, does not report them).
    n_jobs : int, optional
        Clouds computed at once, in threads; None or 1: one after the other (each with the engine's
        own threads), -1: one per core.  With more than one job each cloud's engine runs on one
        thread.  The diagrams do not depend on it.
    output : {"list", "padded"}, default "list"
        ``"list"``: per cloud, one (m, 2) array per homology dimension (ripser's and persim's
        format).  ``"padded"``: one array of shape (n_clouds, n_points, 3) of triples (birth, death,
        dimension), giotto-tda's format: per dimension q, every cloud padded to the most points any
        cloud has in q (at least one) with triples (b_q, b_q, q) on the diagonal, b_q the least
        birth in q over all clouds (0 when there is none).  Unlike giotto-tda, essential classes
        keep their death ∞ and the essential H₀ class is kept.
    metric : {"euclidean", "precomputed"}, default "euclidean"
        Each item of ``X`` is a point cloud, or (``"precomputed"``) a distance matrix: dense and
        symmetric, or scipy.sparse whose stored entries are the only edges (as
        :func:`~thesis_lib.persistence.rips_persistence`'s ``distance_matrix``).

    Examples
    --------
    >>> import numpy as np
    >>> square = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
    >>> RipsDiagrams(homology_dimensions=(1,), scale="diameter").fit_transform([square])[0][0].tolist()
    [[1.0, 1.4142135623730951]]
    """

    def __init__(self, *, max_radius: float = np.inf, max_dim: int = 2, coefficients: int = 2,
                 homology_dimensions: Iterable[int] | None = None, scale: str = "epsilon",
                 min_persistence: float = 0.0, n_jobs: int | None = None, output: str = "list",
                 metric: str = "euclidean") -> None:
        self.max_radius = max_radius
        self.max_dim = max_dim
        self.coefficients = coefficients
        self.homology_dimensions = homology_dimensions
        self.scale = scale
        self.min_persistence = min_persistence
        self.n_jobs = n_jobs
        self.output = output
        self.metric = metric

    def get_params(self, deep: bool = True) -> dict[str, Any]:
        """The constructor's parameters, as scikit-learn's ``BaseEstimator.get_params``.

        Parameters
        ----------
        deep : bool, default True
            Accepted for scikit-learn's interface; there are no nested estimators.

        Returns
        -------
        dict
            ``{"max_radius": ..., "max_dim": ..., "coefficients": ..., "homology_dimensions": ...,
            "scale": ..., "min_persistence": ..., "n_jobs": ..., "output": ..., "metric": ...}``.

        Examples
        --------
        >>> params = RipsDiagrams(max_dim=2).get_params()
        >>> len(params), sorted(params)[:4]
        (9, ['coefficients', 'homology_dimensions', 'max_dim', 'max_radius'])
        >>> params["max_dim"], params["coefficients"], params["scale"]
        (2, 2, 'epsilon')
        """
        return {"max_radius": self.max_radius, "max_dim": self.max_dim, "coefficients": self.coefficients,
                "homology_dimensions": self.homology_dimensions, "scale": self.scale,
                "min_persistence": self.min_persistence, "n_jobs": self.n_jobs, "output": self.output,
                "metric": self.metric}

    def set_params(self, **params: Any) -> RipsDiagrams:
        """Set constructor parameters by name, as scikit-learn's ``BaseEstimator.set_params``.

        Parameters
        ----------
        **params : Any
            New values of ``max_radius``, ``max_dim``, ``coefficients``, ``homology_dimensions``,
            ``scale``, ``min_persistence``, ``n_jobs``, ``output`` or ``metric``.

        Returns
        -------
        RipsDiagrams
            This transformer with the new values (so ``set_params(...).fit_transform(X)`` chains);
            unknown names raise ``ValueError``.

        Examples
        --------
        >>> RipsDiagrams().set_params(scale="diameter").get_params()["scale"]
        'diameter'
        """
        valid = self.get_params()
        for name, value in params.items():
            if name not in valid:
                raise ValueError(f"unknown parameter {name!r} of RipsDiagrams: use one of {sorted(valid)}")
            setattr(self, name, value)
        return self

    def fit(self, X: Iterable[npt.ArrayLike] | None = None, y: Any = None) -> RipsDiagrams:
        """Check the parameters; nothing is learned (the diagrams depend on each cloud alone).

        Parameters
        ----------
        X : iterable of array_like, optional
            Point clouds; ignored.
        y : Any, optional
            Ignored (scikit-learn's signature).

        Returns
        -------
        RipsDiagrams
            This transformer.

        Raises
        ------
        ValueError
            On an invalid ``max_radius``, ``max_dim`` (below 1), ``coefficients`` (not a prime),
            ``homology_dimensions`` (empty, negative, or disagreeing with ``max_dim``), ``scale``,
            ``min_persistence``, ``n_jobs`` (not -1 or a positive integer), ``output`` or ``metric``.

        Examples
        --------
        >>> transformer = RipsDiagrams()
        >>> transformer.fit() is transformer
        True
        """
        self._parameters()
        return self

    def _parameters(self) -> tuple[float, int, Field, tuple[int, ...]]:
        """The parameters parsed: (ε, max_dim, field, the homology dimensions returned), or the
        ValueError naming the bad one."""
        eps = check_radius(self.max_radius)
        max_dim = check_max_dim(self.max_dim, maximum=MAX_DIM)
        field = parse_field(self.coefficients, field=True)
        check_scale(self.scale)
        check_min_persistence(self.min_persistence)
        _jobs(self.n_jobs)
        check_choice(self.output, OUTPUTS, "output")
        if self.metric not in METRICS:
            raise ValueError(f"metric must be one of {', '.join(map(repr, METRICS))}, got {self.metric!r}")
        if self.homology_dimensions is None:
            if max_dim < 1:
                raise ValueError("max_dim must be >= 1: the top dimension of the complex has no complete homology")
            return eps, max_dim, field, tuple(range(max_dim))
        dims = _homology_dimensions(self.homology_dimensions)
        if max_dim not in (2, dims[-1] + 1):  # 2: max_dim left at its default
            raise ValueError(f"max_dim={max_dim} and homology_dimensions={self.homology_dimensions!r} disagree: H"
                             f"{dims[-1]} needs max_dim={dims[-1] + 1} (give homology_dimensions alone)")
        return eps, dims[-1] + 1, field, dims

    def transform(self, X: Iterable[npt.ArrayLike]) -> list[list[np.ndarray]] | np.ndarray:
        """The persistence diagrams of each point cloud.

        Parameters
        ----------
        X : iterable of array_like, each of shape (n_i, d)
            Point clouds (finite), or with ``metric="precomputed"`` distance matrices.  Duplicate
            points are allowed: each row is a vertex, joined to its copies at 0 (their H0 bars have
            length zero and are left out).

        Returns
        -------
        list of list of ndarray, or ndarray
            For each cloud, one array of shape (m, 2) per homology dimension (0 .. max_dim − 1, or
            the sorted ``homology_dimensions``): the (birth, death) pairs (``inf`` for essential
            classes) in ``scale``'s values, as ``Barcode.to_diagrams``; with ``output="padded"``
            the array of triples of shape (n_clouds, n_points, 3) described above.

        Warns
        -----
        UserWarning
            A cloud square, symmetric, with a zero diagonal and no negative entry: it looks like a
            distance matrix but is read as n points in R^n (ripser.py warns too).

        Raises
        ------
        ValueError
            On invalid parameters or an invalid point cloud (the message names the cloud).

        Examples
        --------
        The unit square and the square of side 2: H_1 is born at ε = 1/2 and dies at √2/2, both doubled:

        >>> import numpy as np
        >>> square = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
        >>> diagrams = RipsDiagrams(max_dim=2).transform([square, 2 * square])
        >>> [np.round(d[1], 6).tolist() for d in diagrams]
        [[[0.5, 0.707107]], [[1.0, 1.414214]]]
        >>> diagrams[0][0].tolist()
        [[0.0, 0.5], [0.0, 0.5], [0.0, 0.5], [0.0, inf]]
        """
        eps, max_dim, field, dims = self._parameters()
        if X is None or isinstance(X, (str, bytes)) or not isinstance(X, Iterable):
            raise InvalidTypeError(f"X must be a list of point clouds, got {type(X).__name__}")
        if isinstance(X, np.ndarray) and X.ndim == 2:
            raise ValueError("X must be a list of point clouds; got one 2-D array (wrap it in a list)")
        clouds = []
        for i, cloud in enumerate(X):
            try:
                clouds.append(parse_rips_input(None, cloud, sparse=True) if self.metric == "precomputed"
                              else parse_points(cloud, warn_square=True))
            except ValueError as err:
                raise ValueError(f"{'distance matrix' if self.metric == 'precomputed' else 'point cloud'} {i}: {err}") \
                    from None
        jobs = _jobs(self.n_jobs)
        threads = 1 if jobs > 1 else 0  # one engine thread per job; alone, the engine's own default

        def diagrams(points) -> list[np.ndarray]:
            barcode = rips_barcode(points, eps, max_dim, field, n_threads=threads)
            out = barcode.to_diagrams(dims=range(max_dim), scale=self.scale, min_persistence=self.min_persistence)
            return [out[k] for k in dims]

        if jobs > 1 and len(clouds) > 1:
            with ThreadPoolExecutor(max_workers=min(jobs, len(clouds))) as pool:
                result = list(pool.map(diagrams, clouds))
        else:
            result = [diagrams(points) for points in clouds]
        return _padded(result, dims) if self.output == "padded" else result

    def fit_transform(self, X: Iterable[npt.ArrayLike], y: Any = None) -> list[list[np.ndarray]] | np.ndarray:
        """:meth:`fit`, then :meth:`transform`.

        Parameters
        ----------
        X : iterable of array_like, each of shape (n_i, d)
            Point clouds.
        y : Any, optional
            Ignored.

        Returns
        -------
        list of list of ndarray
            As :meth:`transform`.

        Examples
        --------
        >>> import numpy as np
        >>> square = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
        >>> np.round(RipsDiagrams(homology_dimensions=(1,)).fit_transform([square])[0][0], 6).tolist()
        [[0.5, 0.707107]]
        """
        return self.fit(X, y).transform(X)

    def __repr__(self) -> str:
        args = ", ".join(f"{k}={v!r}" for k, v in self.get_params().items())
        return f"RipsDiagrams({args})"


def _homology_dimensions(dims) -> tuple[int, ...]:
    """``homology_dimensions`` as a sorted tuple of distinct integers in 0 .. MAX_DIM − 1 (not empty)."""
    if isinstance(dims, (str, bytes)) or not isinstance(dims, Iterable):
        raise InvalidTypeError(f"homology_dimensions must be an iterable of integers, got {dims!r}")
    out = tuple(sorted({check_int(d, "a homology dimension", minimum=0, maximum=MAX_DIM - 1) for d in dims}))
    if not out:
        raise ValueError("homology_dimensions is empty")
    return out


def _jobs(n_jobs: object) -> int:
    """The number of threads ``n_jobs`` asks for (None: 1, -1: one per core), or the ValueError."""
    if n_jobs is None:
        return 1
    if isinstance(n_jobs, (int, np.integer)) and not isinstance(n_jobs, bool) and int(n_jobs) == -1:
        return os.cpu_count() or 1
    return check_int(n_jobs, "n_jobs (-1 for one per core)", minimum=1)


def _padded(result: list[list[np.ndarray]], dims: tuple[int, ...]) -> np.ndarray:
    """giotto-tda's layout: per dimension, every cloud padded to the most points with (b, b, q) triples."""
    blocks = []
    for j, q in enumerate(dims):
        arrays = [d[j] for d in result]
        rows = max(1, max((len(a) for a in arrays), default=0))
        births = [a[:, 0].min() for a in arrays if len(a)]
        pad = float(min(births)) if births else 0.0
        block = np.full((len(arrays), rows, 3), [pad, pad, q], dtype=np.float64)
        for i, a in enumerate(arrays):
            block[i, : len(a), :2] = a
        blocks.append(block)
    return np.concatenate(blocks, axis=1) if blocks else np.zeros((len(result), 0, 3))
