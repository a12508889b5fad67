// tiershade glue: the HDR demo and benchmark scene: the sphere grid of the model
// lighting demo (glue/demo/sphere_grid_scene.h) in front of a lit back wall, under two lightings
// with a real dynamic range: daylight (a sun, a sky ambient cube from a real light probe,
// a hot spot light on the wall) and a dark room (one dim lamp).
#pragma once
#include <string>

#include "demo/sphere_grid_scene.h"

// Daylight; the ambient cube comes from the lat-long probe at probe_path when it can be
// read (else a procedural sky cube); *note says which.
SphereScene hdr_daylight_scene(const std::string &probe_path, std::string *note);
SphereScene hdr_dark_room_scene();

// The probe the demo and benchmark use: $TIERSHADE_PROBE_HDR, else
// ../shared/data/probes/uffizi.hdr (relative to the repository, where make runs).
std::string hdr_default_probe();

// sphere_frame() for an sm3 tier (4 local lights), with the background pixels turned into
// a wall facing the camera at z = -1.2 (normal +Z), so that every pixel is lit.
bool hdr_scene_frame(const SphereScene &scene, int w, int h, SphereFrame *out, std::string *err);
