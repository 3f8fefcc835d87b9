# thesis-lab: `make book` builds the whole book, `make test` runs the whole test suite.
# Both create .venv with the project installed (editable, with the dev extras) when it is missing.

PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed
export PATH := $(abspath $(BIN)):$(PATH)
export PYDEVD_DISABLE_FILE_VALIDATION := 1
export VTK_DEFAULT_OPENGL_WINDOW := vtkEGLRenderWindow

.PHONY: book test experiments notebooks sweep bench bench-check clean install chromium

install: $(STAMP)

$(STAMP): pyproject.toml
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e ".[dev]"
	touch $(STAMP)

## book: execute every notebook (cached in .jupyter_cache) and build the HTML book
book: $(STAMP)
	$(BIN)/jupyter-book build book -W -n --keep-going

## test: library tests, notebooks against their stored outputs (nbval), the built book in Chromium
test: $(STAMP) chromium
	$(BIN)/python -m pytest -n 2 --dist loadfile -p no:cacheprovider \
	    tests book experiments --nbval --nbval-sanitize-with tests/nbval_sanitize.cfg \
	    --nbval-current-env

chromium:
	@command -v chromium >/dev/null 2>&1 || { \
	    echo "installing Debian's chromium for the offline math test"; \
	    SUDO=$$( [ "$$(id -u)" = 0 ] || echo sudo ); \
	    $$SUDO apt-get update -qq && DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -qq chromium >/dev/null; }

## experiments: re-execute every experiment with its defaults, in place (the stored default runs)
experiments: $(STAMP)
	$(BIN)/thesis-lab store

## notebooks: re-execute the book's chapter notebooks in place
notebooks: $(STAMP)
	$(BIN)/thesis-lab store $(wildcard book/*.ipynb)

## sweep: the sweeps the book shows, e.g. make sweep NAME=two-circles ARGS="-p n_per_circle 60 100"
sweep: $(STAMP)
	$(BIN)/thesis-lab sweep $(NAME) $(ARGS) -j 2

## bench: speed and memory against the reference libraries (interleaved rounds, medians, paired
## ratios; writes benchmarks/results/<topic>.json with commit, date and load). make bench ONLY=persistence
bench: $(STAMP)
	for b in $(if $(ONLY),benchmarks/bench_$(ONLY).py,benchmarks/bench_*.py); do echo "== $$b"; $(BIN)/python $$b || exit 1; done

## bench-check: re-run every benchmark's quick cases; fail if a stored ratio moved by more than 35 %
bench-check: $(STAMP)
	$(BIN)/python benchmarks/check.py

clean:
	rm -rf book/_build .jupyter_cache runs .pytest_cache .hypothesis
