"""Drop-in replacements for other libraries' entry points, computed by thesis_lib's engines.

``ripser(X, ...)`` answers ripser.py's ``ripser.ripser`` call with the same dictionary.
"""

from .ripser import ripser

__all__ = ["ripser"]
