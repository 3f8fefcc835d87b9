"""Shared input handling for the persistence algorithms: filtrations, (simplex, value) pairs, primes."""

from __future__ import annotations

from collections.abc import Iterable

from ..complexes.filtration import Filtration
from ..simplicial import check_coefficients


def as_filtration(filtration) -> Filtration:
    """A :class:`Filtration` as is; any other iterable of ``(simplex, value)`` pairs via ``from_pairs``."""
    if isinstance(filtration, Filtration):
        if filtration.dimension < 0 or len(filtration) == 0:
            raise ValueError("the filtration is empty")
        return filtration
    if isinstance(filtration, (str, bytes)) or not isinstance(filtration, Iterable):
        raise ValueError(f"expected a Filtration or an iterable of (simplex, value) pairs, got {type(filtration).__name__}")
    return Filtration.from_pairs(filtration)


def check_prime(p) -> int:
    """The coefficient field Z/p: ``p`` must be a prime (Z itself is not a field)."""
    c = check_coefficients(p)
    if c == 0:
        raise ValueError("persistence needs a field: p must be a prime, not 0 (the integers)")
    if c >= 2**31:
        raise ValueError(f"p = {c} is too large (coefficients are stored in 64-bit products), use p < 2**31")
    return c
