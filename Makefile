# hillstab
#   make run            run the default scene (data files + PNG figures in out/)
#   make test           run the test suite
# both install what is missing first (scripts/setup.sh). Further targets:
#   make test-debug     tests again with runtime checks and floating-point traps
#   make bench          speed-against-error benchmark (out/bench_*.dat, out/bench*.png)
#   make lib            build libhillstab.a and .mod files with plain gfortran (no fpm)
#   make install PREFIX=/usr/local   install library, modules, C header, pkg-config and CMake files
#   make check-install  install into build/_install and link a C and a Fortran program against it
#   make mpi            build hillstab and hillstab_mpi with CMake (installs Open MPI: scripts/setup_mpi.sh)
#   make test-mpi       hillstab_mpi against hillstab at np = 1, 2, 3, bad input, failing points
FPM ?= bash scripts/fpm.sh
ifeq ($(origin FC),default)
FC = gfortran
endif
PREFIX ?= /usr/local
DEBUG_FLAGS = -fcheck=all -ffpe-trap=invalid,zero,overflow -g -fbacktrace
LIB_FLAGS = -O2 -fPIC -fopenmp -fimplicit-none
LIBS = -lgsl -lgslcblas -llapack -lblas
FC_VERSION = $(shell $(FC) -dumpversion 2>/dev/null)
MOD_SUBDIR = hillstab/$(notdir $(FC))-$(FC_VERSION)
LEGACY_DIR = build/legacy
VERSION := $(shell sed -n 's/^version = "\(.*\)"/\1/p' fpm.toml)

.PHONY: run test test-debug setup bench lib install check-install clean mpi test-mpi

setup:
	@bash scripts/setup.sh

run: setup
	@bash scripts/run_default.sh

test: setup
	$(FPM) test

test-debug: setup
	$(FPM) test --profile debug --flag "$(DEBUG_FLAGS)"

bench: setup
	mkdir -p out
	$(FPM) run --profile release --flag "$$(bash scripts/release_flags.sh)" hillstab_bench
	gnuplot plots/bench.gp

lib: setup
	@mkdir -p $(LEGACY_DIR)/obj $(LEGACY_DIR)/mod
	@for f in $$(bash scripts/fortran_order.sh); do \
	   echo "  FC $$f"; \
	   $(FC) $(LIB_FLAGS) -J $(LEGACY_DIR)/mod -c $$f -o $(LEGACY_DIR)/obj/$$(basename $$f .f90).o || exit 1; \
	done
	@rm -f $(LEGACY_DIR)/libhillstab.a
	ar rcs $(LEGACY_DIR)/libhillstab.a $(LEGACY_DIR)/obj/*.o

install: lib
	install -d $(DESTDIR)$(PREFIX)/lib/pkgconfig $(DESTDIR)$(PREFIX)/lib/cmake/hillstab \
	   $(DESTDIR)$(PREFIX)/include/$(MOD_SUBDIR)
	install -m 644 $(LEGACY_DIR)/libhillstab.a $(DESTDIR)$(PREFIX)/lib/
	install -m 644 include/hillstab.h $(DESTDIR)$(PREFIX)/include/
	install -m 644 $(LEGACY_DIR)/mod/*.mod $(DESTDIR)$(PREFIX)/include/$(MOD_SUBDIR)/
	sed -e 's|@PREFIX@|$(PREFIX)|g' -e 's|@VERSION@|$(VERSION)|g' -e 's|@MOD_SUBDIR@|$(MOD_SUBDIR)|g' \
	   config/hillstab.pc.in > $(DESTDIR)$(PREFIX)/lib/pkgconfig/hillstab.pc
	sed -e 's|@MOD_SUBDIR@|$(MOD_SUBDIR)|g' -e 's|@VERSION@|$(VERSION)|g' \
	   config/hillstab-config.cmake.in > $(DESTDIR)$(PREFIX)/lib/cmake/hillstab/hillstab-config.cmake

check-install:
	@rm -rf build/_install
	$(MAKE) --no-print-directory install PREFIX=$(CURDIR)/build/_install
	bash config/export/check.sh $(CURDIR)/build/_install

mpi:
	bash scripts/setup_mpi.sh
	cmake -S . -B build/cmake_mpi -DHILLSTAB_MPI=ON -DCMAKE_BUILD_TYPE=Release
	cmake --build build/cmake_mpi -j 2

test-mpi:
	bash scripts/test_mpi.sh

clean:
	rm -rf build out
