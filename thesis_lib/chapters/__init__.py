"""The measurements behind the book's pages: each chapter's computed statements, tables, analyses and
figures, built from the mathematics below (complexes, persistence, curvature, Morse theory) and the
laboratory's results.  Nothing in the mathematical packages imports from here.
"""
