#!/bin/sh
# Remakes grid.obj and, with Radiance's obj2mesh on PATH, grid.rtm (for lib/scene/mesh_test.cpp).
set -eu
cd "$(dirname "$0")"
python3 make_grid.py > grid.obj
printf 'void plastic ground 0 0 5 .4 .5 .3 0 0\n' > ground.rad
obj2mesh -a ground.rad grid.obj grid.rtm
