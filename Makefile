# The README's two commands: `make reproduce` (the paper's experiment) and `make test`.
# Both create the virtual environment on first use. torch comes pinned to the CPU
# build (see pyproject.toml's `sb3` extra).
PYTHON ?= python3
VENV ?= .venv
BIN := $(VENV)/bin
OUT ?= results/paper2015
PYTEST_ARGS ?=
NOX_ARGS ?=
MUTATION_ARGS ?=
RAY_VENV ?= .venv-ray
TEST_WORKERS ?= 2
# noxfile.py's sessions, longest first (tests/test_ci_config.py checks none is missing)
NOX_SESSIONS := rllib cleanrl core_lowest tianshou supersuit
INTEGRATION_JOBS ?= $(TEST_WORKERS)

.PHONY: setup reproduce test test-slow test-browser test-ray test-integrations $(addprefix nox-,$(NOX_SESSIONS)) test-mutation mutation-full lint docs bench clean

# Set-up prints a step counter and the installer's own report (the packages it resolved,
# prepared and installed), so the minutes of installing are never silent. pip installs uv;
# uv installs the rest (in native code: seconds where pip took a minute of one core), given
# the package sources pip is configured with (.ci/uv_flags.py: local wheels, indexes,
# constraints), so it resolves what pip would. --compile-bytecode: as pip does, the installed
# modules are compiled once here; uv's default leaves them to each import, and where
# PYTHONDONTWRITEBYTECODE is set every new interpreter compiles pandas, torch and the rest
# again (the mutation stage, which starts thousands of test processes, took half as long again).
UV_PIP = $(BIN)/uv pip install --compile-bytecode $$($(BIN)/python .ci/uv_flags.py)
$(BIN)/.installed: pyproject.toml
	@echo "setup [1/3]: creating $(VENV)"
	$(PYTHON) -m venv $(VENV)
	@echo "setup [2/3]: installing the installer, uv, with pip"
	$(BIN)/python -m pip install --progress-bar on "uv>=0.5"
	@echo "setup [3/3]: installing hg-marl with its dev, sb3, video and play extras: numpy, gymnasium, pettingzoo,"
	@echo "             matplotlib, pandas, torch==2.13.0 (CPU), stable-baselines3, sb3-contrib, imageio-ffmpeg,"
	@echo "             starlette, uvicorn, pytest, ruff, mypy, nox (under a minute to several, with the downloads)"
	$(UV_PIP) --python $(BIN)/python -e ".[dev,sb3,video,play]"
	@echo "setup: done ($(VENV))"
	touch $@

setup: $(BIN)/.installed

reproduce: setup
	$(BIN)/hg-marl reproduce --out $(OUT)

# The tests are independent: pytest-xdist spreads them over the cores (TEST_WORKERS=1: one process).
test: setup lint
	$(BIN)/python -m pytest -n $(TEST_WORKERS) -m "not slow and not integrations and not browser and not ray" $(PYTEST_ARGS)

test-slow: setup
	$(BIN)/python -m pytest -n $(TEST_WORKERS) -m "slow and not integrations and not browser and not ray" $(PYTEST_ARGS)

# The MARL libraries (Tianshou, RLlib, SuperSuit+SB3, CleanRL-style, make_vec) and the
# lowest gymnasium and pettingzoo (the newest are make test's), each in its own nox environment (noxfile.py),
# two sessions at a time (INTEGRATION_JOBS), longest first; each session's output is
# printed whole when it ends (--output-sync), so the two never interleave.
test-integrations: setup
	@echo "integrations: nox sessions $(NOX_SESSIONS), $(INTEGRATION_JOBS) at a time; each prints when it ends"
	$(MAKE) --no-print-directory -j$(INTEGRATION_JOBS) --output-sync=target $(addprefix nox-,$(NOX_SESSIONS))

$(addprefix nox-,$(NOX_SESSIONS)): nox-%: setup
	$(BIN)/nox -s $* $(NOX_ARGS)

# The web front end in a real headless Chromium: Debian's chromium (installed with
# apt-get when missing) driven by Playwright with the system executable.
test-browser: setup
	$(UV_PIP) --quiet --python $(BIN)/python -e ".[play,browser-test]"
	test -x /usr/bin/chromium || (apt-get update -qq && apt-get install -y -qq chromium)
	mkdir -p artifacts
	HG_MARL_BROWSER_REQUIRED=1 $(BIN)/python -m pytest -m browser $(PYTEST_ARGS)

# Mutation testing (mutation/README.md): a seeded sample of mutants per module of
# mutation/modules.toml; prints the score per module and every survivor.
$(BIN)/.mutation: $(BIN)/.installed
	$(UV_PIP) --quiet --python $(BIN)/python -e ".[dev,sb3,video,play,mutation]"
	touch $@

test-mutation: $(BIN)/.mutation
	$(BIN)/python mutation/run.py $(MUTATION_ARGS)

# Every mutant of every module (hours on 2 cores; see mutation/README.md).
mutation-full: $(BIN)/.mutation
	$(BIN)/python mutation/run.py --full $(MUTATION_ARGS)
# Ray may pull other versions of shared dependencies, so it gets its own environment,
# without the sb3 extra (HG_MARL_REQUIRE_EXTRAS=0: the Ray tests need only Ray).
$(RAY_VENV)/bin/.installed: pyproject.toml $(BIN)/.installed
	$(PYTHON) -m venv $(RAY_VENV)
	$(UV_PIP) --quiet --python $(RAY_VENV)/bin/python -e ".[dev,ray]"
	touch $@

test-ray: $(RAY_VENV)/bin/.installed
	HG_MARL_RAY_STAGE=1 HG_MARL_REQUIRE_EXTRAS=0 $(RAY_VENV)/bin/python -m pytest -m ray tests/training/test_ray.py $(PYTEST_ARGS)

lint: setup
	$(BIN)/ruff check .
	$(BIN)/mypy
	$(BIN)/python .ci/lint_layers.py

# The documentation site (mkdocs.yml): strict, so a page missing from the nav, a broken
# link or anchor fails the build. CI runs it as its own stage, after `make test`.
$(BIN)/.docs: $(BIN)/.installed
	$(UV_PIP) --quiet --python $(BIN)/python -e ".[docs]"
	touch $@

docs: $(BIN)/.docs
	$(BIN)/mkdocs build --strict --site-dir build/site

bench: setup
	$(BIN)/python benchmarks/env_throughput.py
	$(BIN)/python benchmarks/planner_latency.py
	$(BIN)/python benchmarks/decision_latency.py

clean:
	rm -rf $(VENV) $(RAY_VENV) results build/site .pytest_cache .mypy_cache .ruff_cache
