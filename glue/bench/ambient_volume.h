// tiershade bench: the ambient section's model frame error against per-pixel ray-traced ground truth
// on a shipped scene with world and models, by cube source, lookup, fit and volume density
// (ambient_volume.cpp; docs/accuracy_cost.md).
#pragma once
#include <sstream>
#include <string>

// Appends the section's tables to `o`.
bool ambient_volume_rows(std::ostringstream &o, std::string *err);
