# thesis-lab: `make book` builds the whole book, `make test` runs the whole test suite.
# Both create .venv with the project installed (editable, with the dev extras) when it is missing.

SHELL  := /bin/bash
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed
export PATH := $(abspath $(BIN)):$(PATH)
export PYDEVD_DISABLE_FILE_VALIDATION := 1
export VTK_DEFAULT_OPENGL_WINDOW := vtkEGLRenderWindow

.PHONY: book test test-sanitize experiments notebooks sweep bench bench-check clean install chromium

# $(call unchanged,COMMAND): run COMMAND, then fail if it changed what `git status` shows
define unchanged
	@before="$$(git status --porcelain 2>/dev/null)"; \
	echo '$(strip $(1))'; $(1); rc=$$?; \
	after="$$(git status --porcelain 2>/dev/null)"; \
	if [ "$$before" != "$$after" ]; then \
	    echo "error: this command changed files of the checkout (git status before / after):"; \
	    diff <(echo "$$before") <(echo "$$after"); exit 1; fi; \
	exit $$rc
endef

install: $(STAMP)

# The compiled core (src/*.cpp) is built by scikit-build-core into build/ (kept: a C++ change
# recompiles only what changed, and `make test` / `make book` reinstall when a source is newer).
# The editable install maps the package's files when it is made: when a module is added, moved or
# removed, the list below changes and the project is installed again.
MODULES := $(VENV)/.modules
$(shell mkdir -p $(VENV) && find thesis_lib -name '*.py' -not -path '*/__pycache__/*' | LC_ALL=C sort > $(MODULES).new \
    && { cmp -s $(MODULES).new $(MODULES) && rm -f $(MODULES).new || mv -f $(MODULES).new $(MODULES); })

$(STAMP): pyproject.toml CMakeLists.txt $(wildcard src/*.cpp src/*.hpp) $(MODULES)
	@command -v c++ >/dev/null 2>&1 || command -v g++ >/dev/null 2>&1 || command -v clang++ >/dev/null 2>&1 || { \
	    echo "error: thesis_lib's compiled core needs a C++17 compiler and none was found (Debian/Ubuntu: apt-get install g++)"; exit 1; }
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	@# without build isolation every sdist among the dependencies (pykeops, via multipers) builds with
	@# this venv's own setuptools, which must have bdist_wheel
	$(BIN)/python -m pip install --quiet "scikit-build-core>=0.10" "nanobind>=2.4" "setuptools>=70.1" "wheel>=0.43"
	$(BIN)/python -m pip install --quiet --no-build-isolation -e ".[dev]"
	touch $(STAMP)

## book: execute every notebook (cached in book/_build/.jupyter_cache) and build the HTML book,
## book/_build/html, and the same site as one archive, book/_build/thesis-lab-book.zip
book: $(STAMP)
	$(call unchanged,$(BIN)/jupyter-book build book -W -n --keep-going)

## test: library tests, notebooks against their stored outputs (nbval) and again under other
## numerics (tests/test_machine_independence.py), the built book in Chromium
test: $(STAMP) chromium
	$(call unchanged,$(BIN)/python -m pytest -n 2 --dist loadfile -p no:cacheprovider \
	    tests book experiments --nbval --nbval-sanitize-with tests/nbval_sanitize.cfg \
	    --nbval-current-env)

## test-sanitize: the compiled core built with AddressSanitizer and UndefinedBehaviorSanitizer
## (build/sanitize), under its kernel, fuzz and cross-check tests (.ci/sanitize)
test-sanitize: $(STAMP)
	$(call unchanged,.ci/sanitize)

chromium:
	@command -v chromium >/dev/null 2>&1 || { \
	    echo "installing Debian's chromium for the tests that open the built book"; \
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

## clean: remove what the commands build (the book, its execution cache, runs, test caches)
clean:
	rm -rf book/_build .jupyter_cache runs .pytest_cache .hypothesis
