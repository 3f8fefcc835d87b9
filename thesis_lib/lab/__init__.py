"""The laboratory around the mathematics: the experiment runner and its command line, stored results,
the reproduction report, the data layer and the benchmark records. Nothing in the mathematical
subpackages imports from here."""
