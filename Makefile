# `make test` and `make reproduce` each set up .venv on their own (idempotently).
VENV := .venv
PYTHON := $(VENV)/bin/python
STAMP := $(VENV)/.installed
# The editable install is a tree of links to the package's files (docs/contributing.md, "The
# layout"), which editors and type checkers follow: it is made again when a file is added or
# removed.
FILES := $(sort $(wildcard sweeps/*.py sweeps/*/*.py sweeps/py.typed models/*.py studies/*.py \
                           studies/*/*.toml studies/*/*.md studies/*/*.py))
ifneq ($(FILES),$(shell cat $(VENV)/.files 2>/dev/null))
.PHONY: $(STAMP)
endif

.PHONY: test test-slow reproduce studies studies-on-cluster studies-in-process docs bench clean

# uv installs what pip would, in a fraction of the time (it fetches and unpacks in parallel);
# where it cannot be had or cannot reach the index, pip does the same install.
INSTALL = $(VENV)/bin/uv pip install --quiet --python $(PYTHON) \
	--config-settings editable_mode=strict
PIP_INSTALL = $(PYTHON) -m pip install --quiet --disable-pip-version-check \
	--config-settings editable_mode=strict
# The bytecode of what the studies' and the tests' processes import, written by importing it
# (two processes, a core each): compiling every module of the environment (uv's
# --compile-bytecode, pip's default) takes three times as long, most of it for modules no run
# imports, and where Python may not write bytecode as it runs (PYTHONDONTWRITEBYTECODE), every
# process would compile its imports again. A module missing from another version of a
# dependency costs only its bytecode.
RUN_IMPORTS := bearing_sweep.cli, bearing_sweep.study, bearing_sweep.executor, dask.array, \
	distributed.dashboard.scheduler, distributed.cli.dask_worker, distributed.http.health, \
	distributed.http.statics, distributed.http.scheduler.info, \
	distributed.http.scheduler.json, distributed.http.scheduler.prometheus, \
	distributed.http.worker.prometheus, distributed.diagnostics.websocket, \
	tornado.platform.asyncio, pytest, xdist, hypothesis
MORE_RUN_IMPORTS := matplotlib.pyplot, matplotlib.backends.backend_agg, scipy.stats, \
	scipy.optimize, scipy.integrate, scipy.interpolate, scipy.fftpack, netCDF4, h5py, zarr, \
	pint, xarray, xarray.computation.nanops, numba.core.registry
# numba's contexts import their implementations, as the first compiled call does.
NUMBA_CONTEXTS := target = numba.core.registry.cpu_target; \
	target.target_context.refresh(); target.typing_context.refresh()
BYTECODE = env -u PYTHONDONTWRITEBYTECODE $(PYTHON) -c 'import $(RUN_IMPORTS)' & \
	env -u PYTHONDONTWRITEBYTECODE $(PYTHON) -c 'import $(MORE_RUN_IMPORTS); $(NUMBA_CONTEXTS)' \
	&& wait $$!
NO_BYTECODE := make: an import above failed; runs compile what it left out as they import it
ENSUREPIP = { $(PYTHON) -m pip --version >/dev/null 2>&1 \
	|| $(PYTHON) -m ensurepip --default-pip --upgrade >/dev/null; }

# The venv is made without pip (ensurepip's install of it takes seconds): python3's own pip
# puts uv in it, and uv pip with the rest. Where python3 has no pip that can, or uv cannot be
# had, ensurepip gives the venv its pip and pip does the install.
$(STAMP): pyproject.toml
	python3 -m venv --without-pip $(VENV)
	python3 -m pip --python $(PYTHON) install --quiet --disable-pip-version-check uv \
		2>/dev/null || true
	if $(INSTALL) pip -e '.[test,explore]' 2>/dev/null; then \
		$(BYTECODE) || echo '$(NO_BYTECODE)' >&2; \
	else $(ENSUREPIP) && $(PIP_INSTALL) -e '.[test,explore]'; fi
	echo '$(FILES)' > $(VENV)/.files
	touch $(STAMP)

# `make test`: every test but the slow ones (clusters, interrupted and parallel runs, each
# study at its full resolution), in two processes (tests/conftest.py says how they share
# them); `make test-slow` runs the slow ones one at a time, as they start clusters of their
# own. CI runs both.
test: $(STAMP)
	$(PYTHON) -m pytest -q -m "not slow" -n 2 --dist loadgroup

test-slow: $(STAMP) $(VENV)/.ross-installed
	$(PYTHON) -m pytest -q -m slow

# ross, for the slow tests of the rotor-dynamics coefficients (made again when pyproject.toml
# changes).
$(VENV)/.ross-installed: pyproject.toml | $(STAMP)
	$(INSTALL) --compile-bytecode -e '.[test,explore,ross]' 2>/dev/null \
		|| $(PIP_INSTALL) -e '.[test,explore,ross]'
	touch $@

# The documentation's tools, beside the test extras (made again when pyproject.toml changes).
$(VENV)/.docs-installed: pyproject.toml | $(STAMP)
	$(INSTALL) --compile-bytecode -e '.[test,explore,docs,ross]' 2>/dev/null \
		|| $(PIP_INSTALL) -e '.[test,explore,docs,ross]'
	touch $@

# `make docs`: the studies' figures and report (what is missing or stale), the pages written
# from the code, every example run, then the site in docs/_build/html; a warning is an error.
docs: $(VENV)/.docs-installed studies
	$(VENV)/bin/bearing-sweep report
	$(PYTHON) -m sphinx -W --keep-going -q -b html docs docs/_build/html

# The studies of the spatial cage model keep both cores busy with their sweeps; the others
# compute in their own process meanwhile (--workers 0), in the time the cluster leaves: at a
# lower priority (nice), so that they fill the cores the cluster leaves idle (its figures,
# its small sweeps, a worker waiting for the other's last point) rather than slow its
# workers, whose sweeps wait for the slower of the two.
CLUSTER_STUDIES := cage_dynamics_3d cage_slip
OTHER_STUDIES := $(filter-out $(CLUSTER_STUDIES),\
	$(patsubst studies/%/figures.py,%,$(sort $(wildcard studies/*/figures.py))))

studies: $(STAMP)
	$(MAKE) --no-print-directory -j2 studies-on-cluster studies-in-process

# Each study's run writes its page; the index is made from them.
reproduce: studies
	$(VENV)/bin/bearing-sweep report --index

studies-on-cluster: $(STAMP)
	$(VENV)/bin/bearing-sweep study $(CLUSTER_STUDIES)

studies-in-process: $(STAMP)
	nice -n 10 $(VENV)/bin/bearing-sweep study --workers 0 $(OTHER_STUDIES)

bench: $(STAMP)
	$(PYTHON) benchmarks/run_all.py

# numba's compiled code too (docs/contributing.md: a caller in another module keeps its own).
clean:
	rm -rf results figures .pytest_cache docs/_build docs/generated build/compiled
	find . -path ./.venv -prune -o -name '*.nb[ci]' -type f -exec rm -f {} +
