"""Data sets the thesis uses: triangulations, samplers and small example filtrations.

Each topic lives in its own module; this package re-exports their public functions.
"""

from .samplers import flat_torus, noisy_circle, two_circles, two_circles_intersections
