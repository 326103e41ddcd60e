#!/bin/sh
# Makes every picture of the lessons: the diagrams (diagrams.py, python3-matplotlib) and the renders
# of the lessons' own scenes with the settings of the step that shows them (raylab-render), so the
# pictures stay true when the renderer changes. tests/lesson/lesson_pictures_test.cpp checks that
# every PNG here is one this script writes (an argument $here/ and the name in double quotes).
# Usage: lessons/pictures/make.sh [RAYLAB_RENDER]   (default: build/raylab-render)
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
render=${1:-$root/build/raylab-render}
python=/usr/bin/python3   # Debian's, with matplotlib and PIL
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

diagram() { "$python" "$here/diagrams.py" "$@"; }
# render OUT SCENE [raylab-render options]: 480 x 270, seed 1, into the scratch folder.
render() {
    out=$1 scene=$2
    shift 2
    "$render" "$root/scenes/$scene" -q --width 480 --height 270 --seed 1 -o "$tmp/$out" "$@" >/dev/null
}
naive="--set render.sampler=independent --set render.nee=false"

diagram rendering-equation "$here/01-rendering-equation.png"

for spp in 4 16 64; do render "02-$spp.png" default.json $naive --spp $spp; done
diagram strips "$here/02-four-times-the-samples.png" "4 spp" "$tmp/02-4.png" "16 spp" "$tmp/02-16.png" "64 spp" "$tmp/02-64.png"

diagram ray-sphere "$here/03-ray-sphere.png"

render 04.png cornell_box.json --spp 64
diagram palette "$tmp/04.png" "$here/04-cornell-box.png"

diagram slab-test "$here/05-slab-test.png"

for k in 0 1 2 3; do render "06-$k.png" closed_furnace.json --set render.nee=false --set render.exposure=-1 --set render.max_bounces=$k --spp 16; done
diagram strips "$here/06-counting-bounces.png" "0 bounces" "$tmp/06-0.png" "1" "$tmp/06-1.png" "2" "$tmp/06-2.png" "3" "$tmp/06-3.png"

diagram hemisphere-pdf "$here/07-hemisphere-pdf.png"

diagram microfacet-normal "$here/08-microfacet-normal.png"

render 09-bsdf.png lesson_lights.json --set render.nee=false --spp 64
render 09-nee.png lesson_lights.json --set render.nee=true --set render.mis=false --spp 64
diagram strips "$here/09-bsdf-sampling-and-nee.png" "BSDF sampling" "$tmp/09-bsdf.png" "next-event estimation" "$tmp/09-nee.png"

diagram thin-lens "$here/10-thin-lens.png"

render 11-1.png lesson_aliasing.json --spp 1
render 11-64.png lesson_aliasing.json --spp 64
diagram strips "$here/11-one-and-64-samples.png" "1 spp" "$tmp/11-1.png" "64 spp" "$tmp/11-64.png"

render 12.png lesson_one_sphere.json --set materials.ball.albedo=0 --set materials.ball.transmission=1 \
    --set materials.ball.roughness=0 --set materials.ball.ior=1.5 --set render.max_bounces=12 --spp 256
diagram palette "$tmp/12.png" "$here/12-glass-ball.png"

for n in 1 8 64; do render "13-$n.png" default.json $naive --rpp 1 --spp $n; done
diagram strips "$here/13-pass-after-pass.png" "1 pass" "$tmp/13-1.png" "8 passes" "$tmp/13-8.png" "64 passes" "$tmp/13-64.png"

render 14-bsdf.png environment.json --set render.sampler=independent --set render.nee=false --spp 16
render 14-nee.png environment.json --set render.sampler=independent --set render.nee=true --spp 16
diagram strips "$here/14-finding-the-sun.png" "BSDF sampling" "$tmp/14-bsdf.png" "sampling the map too" "$tmp/14-nee.png"

metal="--set materials.grey.albedo=0 --set materials.grey.f0=1 --set materials.grey.roughness=0.5"
wide="--set camera.fov=100 --set render.exposure=-1"   # the whole sphere, and fireflies above the sky's grey
render 15-dcos.png furnace.json $naive $metal $wide --set render.ggx_sampling=d_cos --spp 16
render 15-vndf.png furnace.json $naive $metal $wide --set render.ggx_sampling=vndf --spp 16
diagram strips "$here/15-d-cos-and-visible-normals.png" "D·cos θh" "$tmp/15-dcos.png" "visible normals" "$tmp/15-vndf.png"

diagram tone-curves "$here/16-tone-curves.png"

diagram strata "$here/17-strata.png"

diagram schlick-angle "$here/18-schlick-angle.png"
