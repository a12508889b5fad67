// tiershade scene: orthographic cameras (glTF `"type": "orthographic"`): reading them from a glTF
// camera and their view-projection matrix. The perspective camera is in glue/scene/prepare.cpp.
#pragma once
#include "scene/scene.h"

// The view-projection (column-major, OpenGL clip space) of an orthographic camera for an output of
// the given aspect (width / height). Pixels stay square: the view is the smallest one of the
// output's aspect that holds the camera's xmag x ymag half extents (both fit, one exactly).
void ortho_view_projection(const SceneCamera &c, double aspect, double out[16]);
