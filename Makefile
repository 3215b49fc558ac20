# Everything a fresh clone needs, with only python3 and make.
PY ?= python3
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed

.PHONY: demo test bench clean

$(STAMP): pyproject.toml Makefile
	$(PY) -m venv $(VENV)
	$(BIN)/python -m pip install -q --upgrade pip
	$(BIN)/python -m pip install -q -e '.[test,plot]'
	touch $(STAMP)

demo: $(STAMP)
	$(BIN)/algkin derive chebyshev-lambda --outputs B
	$(BIN)/algkin curve chebyshev-lambda --point P
	$(BIN)/algkin derive arm-string --outputs AB

test: $(STAMP)
	$(BIN)/python -m pytest

bench: $(STAMP)
	$(BIN)/python benchmarks/bench_pipeline.py
	$(BIN)/python benchmarks/bench_evaluation.py

clean:
	rm -rf $(VENV) build *.egg-info
