# tiershade: make deps | all | demo | test | bench
# Warnings are errors. The C reference is built with -ffp-contract=off (no fused
# multiply-adds the GLSL does not have) and runs with FTZ/DAZ set (c_ref/math/ts_math.c).

BUILD    ?= build
SAN      ?=
JOBS     ?= $(shell nproc 2>/dev/null || echo 2)
CC       ?= gcc
CXX      ?= g++
PKGS     := OpenEXR libpng OpenColorIO tinygltf spirv stb
OPT      := -O2 -g
ifeq ($(SAN),1)
OPT      := -O1 -g -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined
endif
# SAN=fuzz (clang only, `make fuzz`): objects instrumented for libFuzzer's coverage, with ASan+UBSan.
ifeq ($(SAN),fuzz)
OPT      := -O1 -g -fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined
endif
CFLAGS   := -std=c99 $(OPT) -Wall -Wextra -Werror -ffp-contract=off -fno-fast-math -Ic_ref
CXXFLAGS := -std=c++17 $(OPT) -Wall -Wextra -Werror -ffp-contract=off -fno-fast-math -Iglue -Ic_ref \
            $(shell pkg-config --cflags $(PKGS) 2>/dev/null)
SANFLAGS := -fsanitize=address,undefined
ifeq ($(SAN),fuzz)
# The C reference is compiled by gcc, uninstrumented (its SIMD code uses GCC target pragmas); the
# readers the harnesses drive are all C++.
CFLAGS   := $(filter-out -fsanitize=% -fno-sanitize%,$(CFLAGS))
# clang-only warnings on code gcc accepts: the libraries' headers as system headers, a private field kept.
CXXFLAGS := $(patsubst -I/usr/%,-isystem /usr/%,$(CXXFLAGS)) -Wno-unused-private-field
endif
LDFLAGS  := $(if $(filter 1,$(SAN)),$(SANFLAGS))
LDLIBS   := -lEGL -lglslang-default-resource-limits -lembree3 $(shell pkg-config --libs $(PKGS) 2>/dev/null) -lpthread -ldl -lm

SHADER_FILES := $(sort $(wildcard shaders/*.glsl shaders/*.fs shaders/*.vs shaders/*.variants))
CASE_FILES   := $(sort $(wildcard tests/conform/*.cases))
# The browser pages tiershade opens in headless Chromium (glue/browser), embedded by their paths.
PAGE_FILES   := $(sort $(wildcard glue/browser/*.html glue/browser/*.js))
C_SRC   := $(sort $(shell find c_ref -name '*.c'))
CXX_SRC := $(sort $(shell find glue -name '*.cpp'))
C_OBJ   := $(C_SRC:%.c=$(BUILD)/obj/%.o)
CXX_OBJ := $(CXX_SRC:%.cpp=$(BUILD)/obj/%.o) $(BUILD)/obj/gen/shader_sources.o
LIB_OBJ := $(C_OBJ) $(filter-out $(BUILD)/obj/glue/main.o,$(CXX_OBJ))
# Every tests/unit/test_*.c or .cpp is a test program (run by tests/run_tests.sh).
UNIT_SRC   := $(sort $(wildcard tests/unit/test_*.c tests/unit/test_*.cpp))
UNIT_TESTS := $(patsubst tests/unit/%,$(BUILD)/tests/%,$(basename $(UNIT_SRC)))

.PHONY: all deps demo test test-fast bench clean FORCE
all: $(BUILD)/tiershade $(UNIT_TESTS)

# Debian packages (see README): installed only when missing, so a second run is quick.
DEB_PKGS := build-essential pkg-config libosmesa6-dev libegl-dev libegl-mesa0 libgles-dev libgbm-dev \
            libglm-dev libopenexr-dev libopencolorio-dev libtinygltf-dev nlohmann-json3-dev libstb-dev \
            libpng-dev glslang-dev spirv-tools spirv-headers libembree-dev \
            clang libclang-rt-14-dev chromium
deps:
	@missing=$$(for p in $(DEB_PKGS); do dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q 'install ok installed' || echo $$p; done); \
	if [ -n "$$missing" ]; then \
	  echo "deps: installing$$(echo ' '$$missing)"; \
	  SUDO=$$( [ "$$(id -u)" = 0 ] || echo sudo ); \
	  $$SUDO apt-get update -q && DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -q $$missing; \
	else echo "deps: all $(words $(DEB_PKGS)) packages present"; fi

$(BUILD)/tools/embed_files: tools/embed_files.c
	@mkdir -p $(dir $@)
	$(CC) -std=c99 -O1 -Wall -Wextra -Werror -o $@ $<

# The list of embedded files, rewritten only when the set changes: a file added (or removed) with an
# older time stamp than the generated sources still regenerates them.
$(BUILD)/gen/embedded_files.list: FORCE
	@mkdir -p $(dir $@)
	@echo '$(SHADER_FILES) $(CASE_FILES) $(PAGE_FILES)' | cmp -s - $@ || echo '$(SHADER_FILES) $(CASE_FILES) $(PAGE_FILES)' > $@
FORCE:

$(BUILD)/gen/shader_sources.cpp: $(SHADER_FILES) $(CASE_FILES) $(PAGE_FILES) $(BUILD)/gen/embedded_files.list $(BUILD)/tools/embed_files
	@mkdir -p $(dir $@)
	$(BUILD)/tools/embed_files $@ $(foreach f,$(SHADER_FILES),$(notdir $(f))=$(f)) $(foreach f,$(CASE_FILES),$(f)=$(f)) $(foreach f,$(PAGE_FILES),$(f)=$(f))

$(BUILD)/obj/gen/shader_sources.o: $(BUILD)/gen/shader_sources.cpp
	@mkdir -p $(dir $@)
	$(CXX) $(CXXFLAGS) -MMD -MP -c -o $@ $<

$(BUILD)/obj/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -MMD -MP -c -o $@ $<

$(BUILD)/obj/%.o: %.cpp
	@mkdir -p $(dir $@)
	$(CXX) $(CXXFLAGS) -MMD -MP -c -o $@ $<

$(BUILD)/tiershade: $(BUILD)/obj/glue/main.o $(LIB_OBJ)
	$(CXX) $(LDFLAGS) -o $@ $^ $(LDLIBS)

$(BUILD)/tests/%: $(BUILD)/obj/tests/unit/%.o $(LIB_OBJ)
	@mkdir -p $(dir $@)
	$(CXX) $(LDFLAGS) -o $@ $^ $(LDLIBS)

# --- bundle test (docs/bundles.md): a bare GL program with no tiershade code (no -Iglue, no
# library objects), only EGL, GL headers and nlohmann json; GL through eglGetProcAddress.
BARE_GL := $(BUILD)/tests/bare_gl_render
all: $(BARE_GL)
$(BARE_GL): tests/bundle/bare_gl_render.cpp
	@mkdir -p $(dir $@)
	$(CXX) -std=c++17 $(OPT) -Wall -Wextra -Werror $(LDFLAGS) -o $@ $< -lEGL
# --- end bundle test

# --- fuzzing (docs/reliability.md): the libFuzzer harnesses tests/fuzz/fuzz_*.cpp, built by clang
# (libFuzzer: libclang-rt-14-dev) with ASan+UBSan.
# Only the readers' components are compiled again for the harnesses (FUZZ_CXX_SRC, in build/fuzz/,
# with coverage instrumentation): what else a harness reaches comes, uninstrumented, from the
# ordinary build's objects in build/libtiershade.a (the linker takes just the members it needs; the
# C reference was never instrumented here, its SIMD code uses GCC target pragmas). That keeps
# `make test`'s third build to a fifth of the library.
# `make fuzz FUZZ_SECONDS=60` runs each for that long; `make test` replays the corpora and the
# past crashes (tests/fuzz/regressions/) and runs each briefly (tests/run_tests.sh).
FUZZ_SECONDS ?= 60
FUZZ_SRC  := $(sort $(wildcard tests/fuzz/fuzz_*.cpp))
FUZZ_BINS := $(patsubst tests/fuzz/%.cpp,$(BUILD)/fuzzers/%,$(FUZZ_SRC))
FUZZ_CXX_SRC := $(filter glue/io/% glue/base/% glue/scene/gltf_% glue/scene/textures.cpp \
                glue/color/ocio_lut_bake.cpp glue/bake/ambient_fit.cpp glue/bake/bake_dir.cpp \
                glue/bake/bake_checkpoint.cpp glue/bake/volume_file.cpp,$(CXX_SRC))
FUZZ_OBJ  := $(FUZZ_CXX_SRC:%.cpp=$(BUILD)/obj/%.o)
FUZZ_REST ?= build/libtiershade.a
.PHONY: fuzz fuzz-build fuzz-bins
fuzz-bins: $(FUZZ_BINS)
$(BUILD)/fuzzers/%: tests/fuzz/%.cpp tests/fuzz/fuzz_util.h $(FUZZ_OBJ) $(FUZZ_REST)
	@mkdir -p $(dir $@)
	$(CXX) $(CXXFLAGS) -fsanitize=fuzzer,address,undefined -o $@ $< $(FUZZ_OBJ) $(FUZZ_REST) $(LDLIBS)
$(BUILD)/libtiershade.a: $(LIB_OBJ)
	rm -f $@ && ar rcs $@ $^
fuzz-build:
	$(MAKE) -j$(JOBS) build/libtiershade.a
	$(MAKE) -j$(JOBS) BUILD=build/fuzz SAN=fuzz CXX=clang++ FUZZ_REST=$(abspath build/libtiershade.a) fuzz-bins
fuzz: deps fuzz-build
	bash tests/fuzz/run_fuzz.sh build/fuzz/fuzzers $(FUZZ_SECONDS)
# --- end fuzzing

# The README's test command: every unit test, conformance on both backends and all
# APIs, the CLI checks, then the same suite's fast part under ASan+UBSan.
test: deps
	$(MAKE) -j$(JOBS) all
	$(MAKE) -j$(JOBS) BUILD=build/san SAN=1 all
	$(MAKE) fuzz-build
	bash tests/run_tests.sh

demo: deps
	$(MAKE) -j$(JOBS) all
	$(BUILD)/tiershade demo -o out

bench: deps
	$(MAKE) -j$(JOBS) all
	$(BUILD)/tiershade bench -o docs/accuracy_cost.md

clean:
	rm -rf build out

-include $(shell find $(BUILD)/obj -name '*.d' 2>/dev/null)
