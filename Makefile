# Thin wrapper over CMake; the build lives in build/, programs in build/bin/.
BUILD ?= build
PREFIX ?= /usr/local
JOBS ?= $(shell nproc)

.PHONY: all deps programs test demo bench install clean

# The programs, their OpenVDB module and the demo's flame maker: what the demo runs (not the test suite).
PROGRAMS = rtrace rpict mkcache vwrays xform oconv gensky gendaylit gendaymtx epw2wea rmtxop dctimestep daymetrics rcontrib rfluxmtx vismap fds2rad fds2vdb make_flame brume_openvdb

all: $(BUILD)/Makefile
	cmake --build $(BUILD) -j $(JOBS)

programs: $(BUILD)/Makefile
	cmake --build $(BUILD) -j $(JOBS) --target $(PROGRAMS)

$(BUILD)/Makefile: CMakeLists.txt
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=ON -DCMAKE_INSTALL_PREFIX=$(PREFIX)

deps:
	bash .ci/install-deps

test: deps all
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

demo: deps programs
	bash examples/demo.sh $(BUILD)/bin

bench: all
	bash bench/run.sh $(BUILD)/bin

install: all
	cmake --install $(BUILD) --prefix $(PREFIX)

clean:
	rm -rf $(BUILD)
