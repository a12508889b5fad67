// tiershade cli: `--max-memory MIB` (render, bake) and the estimate of what a render of a loaded
// scene will still allocate, checked before it starts (docs/reliability.md, "Limits").
#pragma once
#include <string>

#include "cli/args.h"
#include "scene/scene.h"

// Sets the process's memory limit (io/memory_limit.h) from --max-memory (64..1048576 MiB;
// default 1024), before any input is read.
void apply_max_memory(const Args &a);

// What rendering `s` at w x h will allocate beyond what is resident now: the frame's buffers
// (measured per pixel: see memory_estimate.cpp), the probes' cubes, a lightmap page baked at
// load, the GL driver's share; msaa > 1: the multisampled frame's per-sample buffers. False with
// *why naming the biggest part and the limit.
bool render_fits_memory(const Scene &s, int w, int h, bool gl, bool check, std::string *why, int msaa = 0);
