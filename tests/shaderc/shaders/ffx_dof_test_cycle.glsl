#version 450
#extension GL_GOOGLE_include_directive : require
#include "ffx_dof_test_cycle_a.h"
layout(local_size_x = 8) in;
void main() {}
