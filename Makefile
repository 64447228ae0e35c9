# chaindrive: the set-up contract. `make demo` and `make test` work on a fresh machine
# with Python >= 3.10 and make.
PYTHON ?= python3
VENV := .venv
PY := $(VENV)/bin/python
OUT ?= out
# compiled bytecode (and pytest's rewritten test modules) are cached in __pycache__ and reused:
# a shell that sets PYTHONDONTWRITEBYTECODE would recompile all of src/ and tests/ on every run
# (collection 15 s instead of 8 s of CPU per test process)
unexport PYTHONDONTWRITEBYTECODE

.PHONY: demo test test-fast bench lint clean venv fuzz docs test-dist

$(VENV)/bin/python:
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip

$(VENV)/.installed-all: pyproject.toml | $(VENV)/bin/python
	$(PY) -m pip install --quiet -e '.[all]'
	touch $@

$(VENV)/.installed-test: pyproject.toml | $(VENV)/bin/python
	$(PY) -m pip install --quiet -e '.[test]'
	touch $@ $(VENV)/.installed-all

$(VENV)/.installed-bench: pyproject.toml | $(VENV)/bin/python
	$(PY) -m pip install --quiet -e '.[bench]'
	touch $@ $(VENV)/.installed-all

$(VENV)/.installed-docs: pyproject.toml | $(VENV)/bin/python
	$(PY) -m pip install --quiet -e '.[docs]'
	touch $@ $(VENV)/.installed-all

venv: $(VENV)/.installed-all

demo: $(VENV)/.installed-all
	$(VENV)/bin/chaindrive demo --output $(OUT)
	@echo "Web design studio: run '$(VENV)/bin/chaindrive web' and open http://127.0.0.1:8000/ (works offline)"

test: $(VENV)/.installed-test
	MPLBACKEND=Agg $(PY) -m pytest -n 2 -q

# everything but the slow (> ~5 s), browser and fuzz tests: under a minute on 2 cores
test-fast: $(VENV)/.installed-test
	MPLBACKEND=Agg $(PY) -m pytest -n 2 -q -m "not slow and not browser and not fuzz and not whole"

# the documentation site, offline, warnings as errors: docs/_build/html/index.html
# (the API pages and the gallery are generated anew each time)
docs: $(VENV)/.installed-docs
	rm -rf docs/api docs/auto_examples docs/_build
	MPLBACKEND=Agg $(PY) -m sphinx -b html -W --keep-going -q docs docs/_build/html
	@echo "documentation: docs/_build/html/index.html"

# the built sdist and wheel: the wheel installed into a fresh venv outside the source tree
# runs the demo and the studio's --help (tests/test_dist.py; also part of `make test`)
test-dist: $(VENV)/.installed-test
	MPLBACKEND=Agg $(PY) -m pytest tests/test_dist.py -q -n 0

bench: $(VENV)/.installed-bench
	MPLBACKEND=Agg $(PY) benchmarks/run_all.py

# >= 10,000 generated inputs per surface (CLI, project files, API, web, and schemathesis
# over the web's OpenAPI schema); one summary line each: tracebacks, exit codes outside
# 0/1/2/3, NaN/inf in outputs, calls over 30 s. FUZZ_N=2000 make fuzz for a shorter run.
fuzz: $(VENV)/.installed-test
	MPLBACKEND=Agg $(PY) scripts/fuzz.py --n $${FUZZ_N:-10000}

lint: $(VENV)/.installed-test
	$(VENV)/bin/ruff check src tests benchmarks
	$(VENV)/bin/mypy

clean:
	rm -rf $(VENV) $(OUT) .pytest_cache build dist docs/_build docs/api docs/auto_examples
