#!/bin/bash
# Submits a render job array of TASKS tasks and the encode job that waits for it; prints both ids.
#   SCENE=shot.gltf OUT='frames/shot_####.exr' VIDEO=shot.mp4 TASKS=4 ./submit.sh [sbatch options]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
: "${SCENE:?}" "${OUT:?}" "${VIDEO:?}"
tasks=${TASKS:-4}
render=$(sbatch --parsable --array=0-$((tasks - 1)) --export=ALL "$@" "$here/render_array.sbatch")
render=${render%%;*} # "id;cluster" on federated setups
encode=$(sbatch --parsable --dependency=afterok:"$render" --kill-on-invalid-dep=yes --export=ALL "$@" "$here/encode.sbatch")
echo "render array: $render  encode: ${encode%%;*}"
