#!/bin/bash
# One sitting of Glint against Blender Cycles on the CPU: CPU time to each relMSE (docs/PERFORMANCE.md,
# "Time to an error against Cycles, one sitting").
#
# usage: [SIZE=WxH] [REFERENCE_SPP=N] [PYTHON=python3] app/bench/cycles/sitting.sh GLINT OUT [ROUNDS]   (from the repository root)
#
# Writes the bench scenes (the Cornell box and the bunny room of `glint bench --suite renderer`),
# a REFERENCE_SPP (4096) reference per scene and bounce limit for each renderer (Glint seed 1000, Cycles seed 1),
# then ROUNDS (default 3) interleaved rounds at SIZE (128x128), 4 and 16 bounces: Glint uniform without and
# with 4 x 4 sample blocks at 8, 16, 64 and 256 spp, Glint with blocks and the adaptive goal mean at
# three thresholds, Cycles at 8, 16, 64 and 256 spp (round r uses seed r - 1, Cycles' seeds skip its
# reference's). Each Glint render is timed as a whole process (user + sys); Cycles renders are timed
# by cornell_cycles.py after a warm-up. OUT/glint.csv and OUT/cycles.csv are the raw rows;
# time_to_error.py prints the tables from them. Needs blender, python3-numpy, python3-openimageio.
set -euo pipefail
GLINT=$(realpath "$1"); OUT=$(realpath -m "$2"); ROUNDS=${3:-3}
HERE=$(dirname "$(realpath "$0")")
PYTHON=${PYTHON:-python3}; SIZE=${SIZE:-128x128}; REFERENCE_SPP=${REFERENCE_SPP:-4096}; SITTING=$(date +%Y-%m-%dT%H:%M)
mkdir -p "$OUT"
GLINT_CSV=$OUT/glint.csv; CYCLES_CSV=$OUT/cycles.csv
[ -f "$GLINT_CSV" ] || echo "sitting,scene,bounces,round,config,args,cpu_seconds,relmse" > "$GLINT_CSV"
[ -f "$CYCLES_CSV" ] || echo "sitting,scene,bounces,round,samples,wall_seconds,cpu_seconds,relmse" > "$CYCLES_CSV"
SETS="cornell_box:4 bunny_room:4 cornell_box:16 bunny_room:16"

[ -f "$OUT/scenes/bunny_room.glb" ] ||
    "$GLINT" bench --suite renderer resources/scenes/cornell_box/cornell_box.gltf --out "$OUT/scenes" \
        --size 32x32 --spp 1 --runs 1 --no-convergence --write-scenes > /dev/null

glint_render() { # SCENE BOUNCES SEED OUT.exr ARGS...: the render, timed (user + sys) into OUT/time.txt
    local scene=$1 bounces=$2 seed=$3 exr=$4; shift 4
    /usr/bin/time -f "%U %S" -o "$OUT/time.txt" "$GLINT" render "$OUT/scenes/$scene.glb" --size $SIZE \
        --bounces "$bounces" --seed "$seed" --aovs none --config accumulate --out "$exr" "$@" > /dev/null 2>&1
}

glint_row() { # SCENE BOUNCES ROUND CONFIG ARGS...
    local scene=$1 bounces=$2 round=$3 config=$4; shift 4
    glint_render "$scene" "$bounces" $((round - 1)) "$OUT/image.exr" "$@"
    local cpu error
    cpu=$(awk '{print $1 + $2}' "$OUT/time.txt")
    error=$("$PYTHON" "$HERE/relmse.py" "$OUT/glint_${scene}_$bounces.exr" "$OUT/image.exr" | awk '{print $2}')
    echo "$SITTING,$scene,$bounces,$round,$config,\"$*\",$cpu,$error" | tee -a "$GLINT_CSV"
}

cycles_rows() { # SCENE BOUNCES ROUND
    local scene=$1 bounces=$2 round=$3 dir=$OUT/cycles_${1}_$2
    local reference=(--reference-samples "$REFERENCE_SPP") seed=0
    if [ "$round" -gt 1 ]; then reference=(--reference-exr "$dir/reference.exr"); seed=$round; fi
    mkdir -p "$dir/r$round"
    blender -b --factory-startup --python "$HERE/cornell_cycles.py" -- --scene "$OUT/scenes/$scene.glb" \
        --out "$dir/r$round" --size $SIZE --bounces "$bounces" --samples 8,16,64,256 "${reference[@]}" \
        --seed $seed --threads "$(nproc)" > "$dir/r$round.log" 2>&1
    [ "$round" -gt 1 ] || cp "$dir/r1/cycles_reference.exr" "$dir/reference.exr"
    "$PYTHON" - "$dir/r$round/cycles_convergence.csv" "$SITTING" "$scene" "$bounces" "$round" <<'PY' | tee -a "$CYCLES_CSV"
import csv, sys
path, sitting, scene, bounces, round_ = sys.argv[1:]
for row in csv.DictReader(open(path)):
    if float(row["relmse"]) > 0:  # the reference's own row
        print(f"{sitting},{scene},{bounces},{round_},{row['samples']},{row['seconds']},{row['cpu_seconds']},{row['relmse']}")
PY
}

for set in $SETS; do
    scene=${set%:*}; bounces=${set#*:}
    reference=$OUT/glint_${scene}_$bounces.exr
    [ -f "$reference" ] || glint_render "$scene" "$bounces" 1000 "$reference" --spp "$REFERENCE_SPP" --sample-block 4
done
for round in $(seq "$ROUNDS"); do
    for set in $SETS; do
        scene=${set%:*}; bounces=${set#*:}
        for spp in 8 16 64 256; do
            glint_row "$scene" "$bounces" "$round" "u$spp" --spp $spp
            glint_row "$scene" "$bounces" "$round" "b4u$spp" --spp $spp --sample-block 4
        done
        for threshold in 0.011 0.0055 0.0028; do
            glint_row "$scene" "$bounces" "$round" "b4m$threshold" --spp 1024 --sample-block 4 \
                --adaptive-goal mean --adaptive-threshold $threshold
        done
        cycles_rows "$scene" "$bounces" "$round"
    done
done
"$PYTHON" "$HERE/time_to_error.py" "$GLINT_CSV" "$CYCLES_CSV" --sitting "$SITTING"
