# chaindrive: the set-up contract. `make demo` and `make test` work on a fresh machine
# with Python >= 3.10 and make.
PYTHON ?= python3
VENV := .venv
PY := $(VENV)/bin/python
OUT ?= out

.PHONY: demo test bench lint clean venv fuzz

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

venv: $(VENV)/.installed-all

demo: $(VENV)/.installed-all
	$(VENV)/bin/chaindrive demo --output $(OUT)
	@echo "Web design studio: run '$(VENV)/bin/chaindrive web' and open http://127.0.0.1:8000/ (works offline)"

test: $(VENV)/.installed-test
	MPLBACKEND=Agg $(PY) -m pytest -n 2 -q

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
	rm -rf $(VENV) $(OUT) .pytest_cache build dist
