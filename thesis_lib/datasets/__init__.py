"""Data sets the thesis uses: triangulations, samplers and small example filtrations."""
