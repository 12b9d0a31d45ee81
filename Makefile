# hillstab
#   make run            run the default scene (data files + PNG figures in out/)
#   make test           check that the public API is documented, then run the test suite
# both install what they need when it is missing (scripts/setup.sh NEED...; without root it
# lists what is missing and how to provide it). Further targets:
#   make test-debug     tests again with runtime checks and floating-point traps
#   make test-python    pip install . (the Python package, compiled by CMake) into a fresh virtual
#                       environment build/venv, then its pytest suite (python/tests)
#   make test-sanitize  tests again built with AddressSanitizer and UndefinedBehaviorSanitizer
#                       (any report fails the run, leaks included; scripts/sanitize/)
#   make fuzz           300 mutated scenes, 90 mutated points files, 140 mutated templates, 200
#                       system scenes with mutated matrix files, 80 damaged checkpoints resumed and
#                       48 checkpoints met by system scenes or with a FIFO, directory or link for a
#                       member, on the normal and the trap build (scripts/fuzz.py)
#   make check-memory   valgrind memcheck on small scenes of every task
#   make check-scenes   every scene of data/scenes against the stored checksums of its data lines
#                       (scripts/check_scenes.sh; --update after a change that means to alter them)
#   make check-plots    every plots/*.gp run from a temporary directory on the files of other scenes
#                       (another spring, other ranges): a PNG each and no word from gnuplot (scripts/check_plots.sh)
#   make bench-output   size and run time of a 1000 x 1000 chart per output layout and columns (out/bench_output.dat)
#   make bench-instructions  callgrind counts of a 300 x 300 chart, this tree against BENCH_BASE (compute, text)
#   make bench          charts against the plain C GSL program (bench/chart_gsl.c, scripts/bench_chart.py:
#                       out/bench_chart_gsl.dat, .png), speed-against-error benchmarks (out/bench_*.dat, out/bench*.png), the
#                       transition-curve benchmarks (out/bench_boundaries.dat, out/bench_fourier.dat) and the pendulum
#                       integrators (out/bench_series.dat, out/bench_series.png)
#   make area           where the approximate charts are wrong: misclassified area (out/area*.dat, out/area.png)
#   make lib            build libhillstab.a, libhillstab.so, .mod files and the hillstab program
#                       with plain gfortran (no fpm)
#   make install PREFIX=/usr/local   install libraries, modules, C header, pkg-config and CMake
#                       files and the program (the same files as the CMake install)
#   make doc            the site with FORD into build/doc: guide pages (docs/guide) and API reference
#                       (installs FORD through pip if missing), every relative link checked
#   make doc-check      fail on an undocumented public entity or argument, a README over 150 lines,
#                       a guide page not listed or not current, a broken link of the Markdown
#                       (scripts/doc_check.py)
#   make check-install  install into private prefixes (make and CMake routes) and build and run
#                       consumers against each: C, Fortran (also beside its own pi and wp) and
#                       fixed-form FORTRAN 77 through pkg-config, C and Fortran through CMake
#                       find_package, and every linking route of docs/guide/library.md as printed
#   make mpi            build hillstab and hillstab_mpi with CMake (installs Open MPI: scripts/setup_mpi.sh)
#   make test-mpi       hillstab_mpi against hillstab at np = 1, 2, 3, bad input, failing points
#   make bench-lyapunov chaos map 40 x 40 x 300 periods: hillstab against a plain C GSL program and
#                       lyapunov_largest, interleaved (~2 min; once ~3 min more for the 3000-period
#                       reference); the 400 x 400 x 1000 map estimated from a sample (out/bench_lyapunov*.dat, .png)
#   make bench-python   a 300 x 300 system chart from Python (System.chart) against the same chart by the
#                       library's task (run_scene), same build and threads (scripts/bench_python_system.py)
#   make bench-system   systems of Hill equations: the 300 x 300 pendula-pair chart against the plain C
#                       GSL program (bench/chart_gsl_system.c) at equal accuracy, and the cost against n
#                       (build/bench/system_speed.dat, system_cost.dat, system_cost.png; BENCH_SYSTEM_N)
#   make bench-regions  the tips of every region of a damped 3-mode column against a scan-and-bisect loop
#                       on the same library, counted in monodromies (out/bench_regions.dat)
#   make bench-equation equations in physical time, one thread: Mathieu's chart as an equation against
#                       the built-in model, and the Kapitza chart against a scipy loop (solve_ivp, DOP853;
#                       numpy and scipy pip-installed into build/venv-bench) and the plain C GSL program
#                       (bench/chart_gsl_kapitza.c) at equal accuracy (scripts/bench_equation.py:
#                       out/bench_equation.dat; BENCH_EQUATION_ROUNDS)
FPM ?= bash scripts/fpm.sh
# the release build: native code (scripts/release_flags.sh), GSL, LAPACK, BLAS and the Fortran
# runtime linked from their static archives when installed (scripts/release_link_flags.sh)
RELEASE = --profile release --flag "$$(bash scripts/release_flags.sh)" --link-flag "$$(bash scripts/release_link_flags.sh)"

ifeq ($(origin FC),default)
FC = gfortran
endif
PREFIX ?= /usr/local
# check-install fails on an executable stack (GNU_STACK RWE) in the installed library or
# program, or on a link that warns about one (HILLSTAB_STACK_CHECK=report only reports)
export HILLSTAB_STACK_CHECK ?= fail
DEBUG_FLAGS = -fcheck=all -ffpe-trap=invalid,zero,overflow -g -fbacktrace
LIB_FLAGS = -O2 -fPIC -fopenmp -fimplicit-none
LIBS = -lgsl -lgslcblas -llapack -lblas
FC_VERSION = $(shell $(FC) -dumpfullversion 2>/dev/null)
MOD_SUBDIR = hillstab/$(notdir $(FC))-$(FC_VERSION)
LEGACY_DIR = build/legacy
VERSION := $(shell sed -n 's/^version = "\(.*\)"/\1/p' fpm.toml)
SOVERSION = $(firstword $(subst ., ,$(VERSION)))
SHARED_LIB = libhillstab.so.$(VERSION)

.PHONY: run codes test test-debug test-python test-sanitize setup setup-build setup-test bench bench-fourier bench-output bench-instructions area lib install check-install doc doc-check clean mpi test-mpi bench-lyapunov bench-system bench-python bench-equation bench-regions fuzz check-memory check-scenes check-plots

# what each target needs (scripts/setup.sh installs only what is missing)
setup:
	@bash scripts/setup.sh compiler fpm plot python
setup-build:
	@bash scripts/setup.sh compiler fpm
setup-test:
	@bash scripts/setup.sh compiler fpm python

run:
	@bash scripts/setup.sh compiler fpm plot
	@bash scripts/run_default.sh

# the codes of models, methods and values that C, FORTRAN 77 and Python copy, written from the Fortran tables
codes:
	python3 scripts/codes.py

test: setup-test
	@python3 scripts/doc_check.py
	@python3 scripts/layer_check.py
	@python3 scripts/codes.py --check
	$(FPM) test

# the Python package as a user installs it: a fresh virtual environment, `pip install .`
# (scikit-build-core compiles the library through CMakeLists.txt), then its suite, which compares
# the package's values with the program of the same build (python/tests)
VENV = build/venv
test-python:
	@bash scripts/setup.sh compiler python-package
	rm -rf $(VENV)
	python3 -m venv $(VENV)
	$(VENV)/bin/python -m pip install --quiet ".[test,plot]"
	$(VENV)/bin/python -m pytest -q -p no:cacheprovider python/tests

test-debug: setup-build
	$(FPM) test --profile debug --flag "$(DEBUG_FLAGS)"

# the suite under AddressSanitizer (with LeakSanitizer) and UndefinedBehaviorSanitizer, in the
# debug profile (-O0 -fcheck=bounds): the first UBSan report stops the run (halt_on_error),
# ASan stops at its first error and reports leaks at exit; both make the run fail. No
# suppressions: the two gfortran 12 artefacts the build met are avoided in the code (see
# scripts/sanitize/reproduce.sh). Output unbuffered, so that the lines before a report show.
# SANITIZE_SKIP=SUITE[,SUITE...] leaves suites out (.ci/run: monodromy, see there).
SANITIZE_FLAGS = -fsanitize=address,undefined -fno-omit-frame-pointer -g
SANITIZE_SKIP ?=
test-sanitize: setup-build
	GFORTRAN_UNBUFFERED_PRECONNECTED=y ASAN_OPTIONS=detect_leaks=1 \
	UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
	   $(FPM) test --profile debug --flag "$(SANITIZE_FLAGS)" --link-flag "-fsanitize=address,undefined" \
	   $(if $(SANITIZE_SKIP),-- --skip=$(SANITIZE_SKIP))

# 300 seeded mutations of the shipped scenes, 90 of points files (and of &points file),
# 140 of every task's template, 200 system scenes (matrix files with nulls, empty fields,
# ragged rows; FIFOs; paths across lines; repeats) and 80 damaged checkpoints resumed, on the normal and on the
# trap build (scripts/fuzz.py: whole NaN-free files or one message line, no temp file, in
# time; a damaged checkpoint resumed into the uninterrupted file or refused)
FUZZ_COUNT ?= 300
FUZZ_POINTS_COUNT ?= 90
FUZZ_TEMPLATE_COUNT ?= 140
FUZZ_CHECKPOINT_COUNT ?= 80
FUZZ_SYSTEM_COUNT ?= 200
FUZZ_FOREIGN_CHECKPOINT_COUNT ?= 48
FUZZ_SEED ?= 7
FUZZ_ARGS = --count $(FUZZ_COUNT) --points-count $(FUZZ_POINTS_COUNT) --template-count $(FUZZ_TEMPLATE_COUNT) \
   --checkpoint-count $(FUZZ_CHECKPOINT_COUNT) --system-count $(FUZZ_SYSTEM_COUNT) \
   --foreign-checkpoint-count $(FUZZ_FOREIGN_CHECKPOINT_COUNT) \
   --seed $(FUZZ_SEED)
fuzz: setup-test
	$(FPM) build >/dev/null
	python3 scripts/fuzz.py $(FUZZ_ARGS) --signals \
	   --hillstab "$$($(FPM) run --runner echo hillstab 2>/dev/null | tail -1)"
	$(FPM) build --profile debug --flag "$(DEBUG_FLAGS)" >/dev/null
	python3 scripts/fuzz.py $(FUZZ_ARGS) \
	   --hillstab "$$($(FPM) run --profile debug --flag "$(DEBUG_FLAGS)" --runner echo hillstab 2>/dev/null | tail -1)"

# valgrind memcheck on small scenes of every task (scripts/check_memory.sh)
check-memory:
	@bash scripts/setup.sh compiler fpm valgrind
	$(FPM) build >/dev/null
	bash scripts/check_memory.sh "$$($(FPM) run --runner echo hillstab 2>/dev/null | tail -1)"

check-scenes: setup-build
	bash scripts/check_scenes.sh

check-plots: setup
	bash scripts/check_plots.sh

bench-output: setup-build
	bash scripts/bench_output.sh

BENCH_BASE ?= a5be02a
bench-instructions: setup-build
	bash scripts/bench_instructions.sh $(BENCH_BASE)

bench: setup
	mkdir -p out build
	$(CC) -O2 bench/chart_gsl.c -o build/chart_gsl -lgsl -lgslcblas -lm
	$(FPM) build $(RELEASE) >/dev/null
	python3 scripts/bench_chart.py "$$($(FPM) run $(RELEASE) \
	   --runner echo hillstab 2>/dev/null | tail -1)" build/chart_gsl --rounds 11
	gnuplot plots/bench_chart_gsl.gp
	$(FPM) run $(RELEASE) hillstab_bench
	gnuplot plots/bench.gp
	$(FPM) run $(RELEASE) hillstab_bench_series
	gnuplot plots/bench_series.gp
	$(FPM) run $(RELEASE) hillstab_bench_boundaries
	$(FPM) run $(RELEASE) hillstab_bench_fourier

# a chart of the fourier model (3 harmonics, a sine term) against the plain C GSL program
# (bench/chart_gsl_fourier.c) at equal accuracy, errors against magnus6 at 1e-13
bench-fourier: setup
	mkdir -p out build
	$(CC) -O2 bench/chart_gsl_fourier.c -o build/chart_gsl_fourier -lgsl -lgslcblas -lm
	$(FPM) build $(RELEASE) >/dev/null
	python3 scripts/bench_fourier_chart.py "$$($(FPM) run $(RELEASE) \
	   --runner echo hillstab 2>/dev/null | tail -1)" build/chart_gsl_fourier

area: setup
	mkdir -p out
	$(FPM) run $(RELEASE) hillstab_area
	gnuplot plots/area.gp

lib:
	@bash scripts/setup.sh compiler
	@rm -rf $(LEGACY_DIR)/obj $(LEGACY_DIR)/mod; mkdir -p $(LEGACY_DIR)/obj $(LEGACY_DIR)/mod
	@sources=$$(bash scripts/fortran_order.sh) || exit 1; for f in $$sources; do \
	   echo "  FC $$f"; \
	   obj=$$(echo "$${f#src/}" | sed 's|/|_|g; s|\.f90$$|.o|'); \
	   $(FC) $(LIB_FLAGS) -J $(LEGACY_DIR)/mod -c $$f -o $(LEGACY_DIR)/obj/$$obj || exit 1; \
	done
	@rm -f $(LEGACY_DIR)/libhillstab.a $(LEGACY_DIR)/libhillstab.so*
	ar rcs $(LEGACY_DIR)/libhillstab.a $(LEGACY_DIR)/obj/*.o
	@# shared library: its dependencies recorded (DT_NEEDED), so -lhillstab alone links
	$(FC) -shared -fopenmp -Wl,-soname,libhillstab.so.$(SOVERSION) -o $(LEGACY_DIR)/$(SHARED_LIB) \
	   $(LEGACY_DIR)/obj/*.o $(LIBS) -lm
	ln -sf $(SHARED_LIB) $(LEGACY_DIR)/libhillstab.so.$(SOVERSION)
	ln -sf libhillstab.so.$(SOVERSION) $(LEGACY_DIR)/libhillstab.so
	@# the program links the static library: it runs without LD_LIBRARY_PATH
	$(FC) $(LIB_FLAGS) -I $(LEGACY_DIR)/mod app/hillstab.f90 -o $(LEGACY_DIR)/hillstab \
	   $(LEGACY_DIR)/libhillstab.a $(LIBS) -lm

install: lib
	install -d $(DESTDIR)$(PREFIX)/lib/pkgconfig $(DESTDIR)$(PREFIX)/lib/cmake/hillstab \
	   $(DESTDIR)$(PREFIX)/include/$(MOD_SUBDIR) $(DESTDIR)$(PREFIX)/bin
	install -m 644 $(LEGACY_DIR)/libhillstab.a $(DESTDIR)$(PREFIX)/lib/
	install -m 755 $(LEGACY_DIR)/$(SHARED_LIB) $(DESTDIR)$(PREFIX)/lib/
	ln -sf $(SHARED_LIB) $(DESTDIR)$(PREFIX)/lib/libhillstab.so.$(SOVERSION)
	ln -sf libhillstab.so.$(SOVERSION) $(DESTDIR)$(PREFIX)/lib/libhillstab.so
	install -m 755 $(LEGACY_DIR)/hillstab $(DESTDIR)$(PREFIX)/bin/
	install -m 644 include/hillstab.h $(DESTDIR)$(PREFIX)/include/
	install -m 644 $(LEGACY_DIR)/mod/*.mod $(DESTDIR)$(PREFIX)/include/$(MOD_SUBDIR)/
	sed -e 's|@PREFIX@|$(PREFIX)|g' -e 's|@LIBDIR_REL@|lib|g' -e 's|@VERSION@|$(VERSION)|g' \
	   -e 's|@MOD_SUBDIR@|$(MOD_SUBDIR)|g' config/hillstab.pc.in > $(DESTDIR)$(PREFIX)/lib/pkgconfig/hillstab.pc
	sed -e 's|@MOD_SUBDIR@|$(MOD_SUBDIR)|g' -e 's|@VERSION@|$(VERSION)|g' -e 's|@SHARED_LIB@|$(SHARED_LIB)|g' \
	   -e 's|@SONAME@|libhillstab.so.$(SOVERSION)|g' \
	   config/hillstab-config.cmake.in > $(DESTDIR)$(PREFIX)/lib/cmake/hillstab/hillstab-config.cmake
	sed -e 's|@VERSION@|$(VERSION)|g' config/hillstab-config-version.cmake.in \
	   > $(DESTDIR)$(PREFIX)/lib/cmake/hillstab/hillstab-config-version.cmake

# each route installs into $HOME/opt/hillstab of a home of its own under build/, the prefix
# of the library guide, whose linking routes config/export/guide_routes.sh runs as printed
CHECK_HOME = $(CURDIR)/build/_home
CHECK_HOME_CMAKE = $(CURDIR)/build/_home_cmake
check-install:
	@bash scripts/setup.sh compiler install
	@rm -rf $(CHECK_HOME) $(CHECK_HOME_CMAKE) build/cmake_check
	$(MAKE) --no-print-directory install PREFIX=$(CHECK_HOME)/opt/hillstab
	bash config/export/check.sh $(CHECK_HOME)/opt/hillstab make
	bash config/export/guide_routes.sh $(CHECK_HOME) make
	@if command -v cmake >/dev/null 2>&1; then \
	   cmake -S . -B build/cmake_check -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX=$(CHECK_HOME_CMAKE)/opt/hillstab \
	      >/dev/null && cmake --build build/cmake_check -j 2 >/dev/null && cmake --install build/cmake_check >/dev/null \
	   && bash config/export/check.sh $(CHECK_HOME_CMAKE)/opt/hillstab cmake \
	   && bash config/export/guide_routes.sh $(CHECK_HOME_CMAKE) cmake \
	   && bash config/export/same_files.sh $(CHECK_HOME)/opt/hillstab $(CHECK_HOME_CMAKE)/opt/hillstab; \
	else echo "check-install: cmake not found, CMake route not checked"; fi

mpi:
	bash scripts/setup_mpi.sh
	cmake -S . -B build/cmake_mpi -DHILLSTAB_MPI=ON -DCMAKE_BUILD_TYPE=Release
	cmake --build build/cmake_mpi -j 2

test-mpi:
	bash scripts/test_mpi.sh

# the chaos map: hillstab against the plain C GSL program (bench/lyapunov_gsl.c) and against
# lyapunov_largest, interleaved rounds; the 3000-period reference is computed once (both
# cores, a few minutes) and kept in out/; then the 400 x 400 x 1000 map estimated from a sample
BENCH_LYAPUNOV_N ?= 40
BENCH_LYAPUNOV_PERIODS ?= 300
BENCH_LYAPUNOV_ROUNDS ?= 3
BENCH_ESTIMATE_STRIDE ?= 7
bench-lyapunov: setup
	mkdir -p out build
	$(CC) -O2 bench/lyapunov_gsl.c -o build/lyapunov_gsl -lgsl -lgslcblas -lm
	@test -f out/bench_lyapunov_reference.dat || $(FPM) run $(RELEASE) \
	   hillstab_chaos_reference -- grid $(BENCH_LYAPUNOV_N) 3000 1e-11 out/bench_lyapunov_reference.dat
	$(FPM) run $(RELEASE) hillstab_bench_lyapunov -- map \
	   $(BENCH_LYAPUNOV_N) $(BENCH_LYAPUNOV_PERIODS) $(BENCH_LYAPUNOV_ROUNDS) out/bench_lyapunov_reference.dat build/lyapunov_gsl
	OMP_NUM_THREADS=2 $(FPM) run $(RELEASE) hillstab_bench_lyapunov -- \
	   estimate 400 1000 $(BENCH_ESTIMATE_STRIDE)
	gnuplot plots/bench_lyapunov.gp

# systems of Hill equations: hillstab's Magnus-6 against the plain C GSL program (rk8pd on the
# fundamental matrix) on the pendula pair's chart, errors against GSL at 1e-14, speed at equal
# accuracy; then microseconds and steps per point against the degrees of freedom n
BENCH_SYSTEM_N ?= 300
bench-python: test-python
	build/venv/bin/python scripts/bench_python_system.py

bench-system: setup
	mkdir -p build/bench
	$(CC) -O2 bench/chart_gsl_system.c -o build/chart_gsl_system -lgsl -lgslcblas -lm
	$(FPM) run $(RELEASE) hillstab_bench_system -- --n $(BENCH_SYSTEM_N)
	gnuplot plots/bench_system.gp

# equations in physical time (model 'equation'), one thread: Mathieu written as an equation against
# the built-in model, the Kapitza chart against a scipy loop and the plain C GSL program at equal
# accuracy (the reference, magnus6 at 1e-13, computed once and kept in build/bench/). Without numpy
# and scipy (pip into build/venv-bench fails) the scipy loop is left out and said so.
BENCH_EQUATION_ROUNDS ?= 7
BENCH_VENV = build/venv-bench
bench-equation:
	@bash scripts/setup.sh compiler fpm python-package
	mkdir -p out build/bench
	$(CC) -O2 bench/chart_gsl_kapitza.c -o build/chart_gsl_kapitza -lgsl -lgslcblas -lm
	$(FPM) build $(RELEASE) >/dev/null
	@test -x $(BENCH_VENV)/bin/python || python3 -m venv $(BENCH_VENV)
	@$(BENCH_VENV)/bin/python -c 'import numpy, scipy' 2>/dev/null || $(BENCH_VENV)/bin/python -m pip install \
	   --quiet numpy scipy || echo "bench-equation: numpy and scipy could not be installed: no scipy loop"
	OMP_NUM_THREADS=1 $(BENCH_VENV)/bin/python scripts/bench_equation.py "$$($(FPM) run $(RELEASE) \
	   --runner echo hillstab 2>/dev/null | tail -1)" build/chart_gsl_kapitza --rounds $(BENCH_EQUATION_ROUNDS)

# the tips of every resonance region of Bolotin's damped column against the scan-and-bisect
# loop a user would write on the same library, one thread (out/bench_regions.dat)
bench-regions: setup
	mkdir -p out
	OMP_NUM_THREADS=1 $(FPM) run $(RELEASE) hillstab_bench_regions

doc:
	@bash scripts/setup.sh doc
	@bash scripts/doc.sh

doc-check:
	@bash scripts/setup.sh python
	@python3 scripts/doc_check.py

clean:
	rm -rf build out
