# hillstab: `make run` runs the default scene (data + PNG figures),
# `make test` runs the test suite; both install what is missing first.
FPM ?= fpm
DEBUG_FLAGS = -fcheck=all -ffpe-trap=invalid,zero,overflow -g -fbacktrace

.PHONY: run test test-debug setup bench clean

setup:
	@bash scripts/setup.sh

run: setup
	@bash scripts/run_default.sh

test: setup
	$(FPM) test

test-debug: setup
	$(FPM) test --profile debug --flag "$(DEBUG_FLAGS)"

clean:
	rm -rf build out
