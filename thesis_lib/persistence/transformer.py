"""Persistence diagrams of many point clouds, in scikit-learn's estimator style.

:class:`RipsDiagrams` is a stateless transformer: ``fit`` checks the parameters, ``transform`` maps
a list of point clouds to their Vietoris–Rips persistence diagrams (the implicit engine of
:func:`~thesis_lib.persistence.rips_persistence`, with the parameters parsed once for all the
clouds).  It has ``get_params``/``set_params`` like any scikit-learn estimator, so
``sklearn.base.clone``, ``Pipeline`` and grid searches accept it, but scikit-learn is not needed to
use it.  Diagrams are in the ripser/persim format (one ``(m, 2)`` array per dimension) with this
library's values: ε, half the diameter (ripser reports 2ε).
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

import numpy as np
import numpy.typing as npt

from .._validate import Field, InvalidTypeError, check_max_dim, check_radius, parse_field, parse_points
from .implicit import rips_barcode

__all__ = ["RipsDiagrams"]


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
    """

    def __init__(self, max_radius: float = np.inf, max_dim: int = 2, coefficients: int = 2) -> None:
        self.max_radius = max_radius
        self.max_dim = max_dim
        self.coefficients = coefficients

    def get_params(self, deep: bool = True) -> dict[str, Any]:
        """The constructor's parameters, as scikit-learn's ``BaseEstimator.get_params``.

        Parameters
        ----------
        deep : bool, default True
            Accepted for scikit-learn's interface; there are no nested estimators.

        Returns
        -------
        dict
            ``{"max_radius": ..., "max_dim": ..., "coefficients": ...}``.
        """
        return {"max_radius": self.max_radius, "max_dim": self.max_dim, "coefficients": self.coefficients}

    def set_params(self, **params: Any) -> RipsDiagrams:
        """Set constructor parameters by name, as scikit-learn's ``BaseEstimator.set_params``.

        Parameters
        ----------
        **params : Any
            New values of ``max_radius``, ``max_dim`` or ``coefficients``.

        Returns
        -------
        RipsDiagrams
            This transformer with the new values (so ``set_params(...).fit_transform(X)`` chains);
            unknown names raise ``ValueError``.
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
            On an invalid ``max_radius``, ``max_dim`` (below 1) or ``coefficients`` (not a prime).
        """
        self._parameters()
        return self

    def _parameters(self) -> tuple[float, int, Field]:
        """The parameters parsed: (ε, max_dim, field), or the ValueError naming the bad one."""
        eps = check_radius(self.max_radius)
        max_dim = check_max_dim(self.max_dim)
        if max_dim < 1:
            raise ValueError("max_dim must be >= 1: the top dimension of the complex has no complete homology")
        return eps, max_dim, parse_field(self.coefficients, field=True)

    def transform(self, X: Iterable[npt.ArrayLike]) -> list[list[np.ndarray]]:
        """The persistence diagrams of each point cloud.

        Parameters
        ----------
        X : iterable of array_like, each of shape (n_i, d)
            Point clouds (finite, no duplicate points).

        Returns
        -------
        list of list of ndarray
            For each cloud, ``max_dim`` arrays of shape (m, 2): the (birth, death) pairs of dimensions
            0 .. max_dim − 1 (``inf`` for essential classes), as ``Barcode.to_diagrams``.

        Raises
        ------
        ValueError
            On invalid parameters or an invalid point cloud (the message names the cloud).
        """
        eps, max_dim, field = self._parameters()
        if X is None or isinstance(X, (str, bytes)) or not isinstance(X, Iterable):
            raise InvalidTypeError(f"X must be a list of point clouds, got {type(X).__name__}")
        if isinstance(X, np.ndarray) and X.ndim == 2:
            raise ValueError("X must be a list of point clouds; got one 2-D array (wrap it in a list)")
        out = []
        for i, cloud in enumerate(X):
            try:
                barcode = rips_barcode(parse_points(cloud), eps, max_dim, field)
            except ValueError as err:
                raise ValueError(f"point cloud {i}: {err}") from None
            out.append(barcode.to_diagrams(range(max_dim)))
        return out

    def fit_transform(self, X: Iterable[npt.ArrayLike], y: Any = None) -> list[list[np.ndarray]]:
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
        """
        return self.fit(X, y).transform(X)

    def __repr__(self) -> str:
        args = ", ".join(f"{k}={v!r}" for k, v in self.get_params().items())
        return f"RipsDiagrams({args})"
