#!/bin/bash
# Submit EXPERIMENT as SHARDS Slurm array tasks and a merge job that runs
# once they all succeeded:
#   SHARDS=8 EXPERIMENT=experiments/large/sweep-1e6.toml bash experiments/slurm/submit.sh
# or a random sweep (its command without --out/--shard; NAME names the file):
#   SHARDS=8 SWEEP="sweep3d --samples 1000000 --seed 1" NAME=spin bash experiments/slurm/submit.sh
# Without Slurm (no `sbatch`), the same scripts run here one after another.
set -euo pipefail
cd "$(dirname "$0")/../.."

export EXPERIMENT=${EXPERIMENT:-experiments/large/sweep-1e6.toml}
export OUT=${OUT:-results/shards}
export KICK=${KICK:-kick}
export SHARDS=${SHARDS:-4}
export SWEEP=${SWEEP:-}
export NAME=${NAME:-sweep}
DIR=experiments/slurm

if ! [[ $SHARDS =~ ^[1-9][0-9]*$ ]]; then
    echo "submit.sh: SHARDS=$SHARDS: a whole number of array tasks, at least 1" >&2
    exit 2
fi

# The binary every task runs, checked here rather than on the nodes: a path
# (absolute, so the jobs run this very binary whatever their PATH) to a
# `kick` that answers --version. Build it onto a filesystem the nodes see:
#   cargo install --locked --path crates/kick-cli --root "$PREFIX"; export KICK=$PREFIX/bin/kick
if ! found=$(command -v "$KICK"); then
    echo "submit.sh: KICK=$KICK is not an executable kick binary (nothing there or on PATH)." >&2
    echo "  Build one where the compute nodes see it and point KICK at it:" >&2
    echo "    cargo install --locked --path crates/kick-cli --root \$PREFIX && export KICK=\$PREFIX/bin/kick" >&2
    exit 2
fi
case $found in /*) ;; *) found="$PWD/$found" ;; esac
if ! version=$("$found" --version 2>/dev/null) || [[ $version != kick* ]]; then
    echo "submit.sh: KICK=$KICK ($found) does not run as kick (\`$found --version\` failed or is not kick's)." >&2
    exit 2
fi
export KICK=$found
echo "kick binary: $KICK ($version)" >&2

if command -v sbatch >/dev/null; then
    array=$(sbatch --parsable --array="0-$((SHARDS - 1))" --export=ALL "$DIR/shard.sbatch")
    sbatch --dependency="afterok:${array%%;*}" --export=ALL "$DIR/merge.sbatch"
else
    echo "no sbatch: running the $SHARDS array tasks and the merge here, one after another" >&2
    for ((task = 0; task < SHARDS; task++)); do
        SLURM_ARRAY_TASK_ID=$task SLURM_ARRAY_TASK_COUNT=$SHARDS bash "$DIR/shard.sbatch"
    done
    bash "$DIR/merge.sbatch"
fi
