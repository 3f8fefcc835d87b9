"""The nerve of a finite cover (thesis Definition 2.7)."""

from __future__ import annotations

from collections.abc import Iterable, Sequence

from .._validate import check_max_dim

__all__ = ["nerve", "MAX_NERVE_SIMPLICES"]

#: the largest nerve built (as Python tuples, about 100 bytes each)
MAX_NERVE_SIMPLICES = 10**6


def nerve(cover: Sequence[Iterable], *, max_dim: int | None = None) -> list[tuple[int, ...]]:
    """Simplices J (index tuples into ``cover``) whose sets have a common element.

    Thesis: Definition 2.7, N(U) = {J ⊆ I : ∩_{j∈J} U_j ≠ ∅} (the empty simplex is left out).

    Parameters
    ----------
    cover : sequence of finite sets (any iterables of hashable elements); ``cover[i]`` is U_i.
    max_dim : keep simplices of dimension <= max_dim (default: all).

    Returns
    -------
    list of tuple
        Ascending index tuples sorted by dimension, then lexicographically.  An empty U_i gives no
        vertex.

    Raises
    ------
    ValueError
        If the nerve grows beyond ``MAX_NERVE_SIMPLICES`` (10⁶) simplices (it can have 2^|I| − 1).

    Examples
    --------
    Three sets meeting pairwise but with no common element: the nerve is a hollow triangle.  Once they
    share the element 3, the triangle is filled:

    >>> nerve([{1, 2}, {2, 3}, {3, 1}])
    [(0,), (1,), (2,), (0, 1), (0, 2), (1, 2)]
    >>> nerve([{1, 2, 3}, {2, 3}, {3, 1}])[-1]
    (0, 1, 2)
    """
    if isinstance(cover, (str, bytes)) or not hasattr(cover, "__len__"):
        raise ValueError("cover must be a sequence of sets")
    if max_dim is not None:
        max_dim = check_max_dim(max_dim)
    sets: list[frozenset] = []
    for i, u in enumerate(cover):
        if isinstance(u, (str, bytes)) or not isinstance(u, Iterable):
            raise ValueError(f"cover[{i}] is not a set of elements: {u!r}")
        sets.append(frozenset(u))
    limit = len(sets) if max_dim is None else max_dim + 1
    # depth-first search carrying the running intersection: a set is a coface only if it meets it
    # (an explicit stack: a chain of thousands of overlapping sets must not exhaust the recursion)
    out: list[tuple[int, ...]] = []
    stack = [((i,), u) for i, u in reversed(list(enumerate(sets))) if u]
    while stack:
        simplex, common = stack.pop()
        out.append(simplex)
        if len(out) > MAX_NERVE_SIMPLICES:
            raise ValueError(f"the nerve has more than {MAX_NERVE_SIMPLICES:,} simplices (the sets overlap too "
                             "much); lower max_dim, or build a Čech, Rips or alpha complex for point clouds")
        if len(simplex) >= limit:
            continue
        for j in range(len(sets) - 1, simplex[-1], -1):
            inter = common & sets[j]
            if inter:
                stack.append((simplex + (j,), inter))
    out.sort(key=lambda s: (len(s), s))
    return out
