# The two commands of the README:
#   make run    set up on first use (Debian packages, .venv, PETSc), run the default scene
#   make test   set up on first use, run the test suite
# Extra arguments: make run ARGS="configs/slider.toml -snes_monitor"; make test PYTEST_ARGS="-k film"
VENV ?= .venv
STAMP := $(VENV)/.sealts-ready

.PHONY: setup run test clean
setup: $(STAMP)

$(STAMP): scripts/setup_env.sh pyproject.toml
	SEALTS_VENV=$(abspath $(VENV)) bash scripts/setup_env.sh
	touch $@

run: $(STAMP)
	$(VENV)/bin/sealts run $(ARGS)

test: $(STAMP)
	$(VENV)/bin/python -m pytest $(PYTEST_ARGS)

clean:
	rm -rf results .pytest_cache
