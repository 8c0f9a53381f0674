#!/usr/bin/env bash
# A sweep as a Slurm job array, one shard a task, each writing its own Parquet file; then the
# merge with Polars. The recipe of docs/sweeps.md ("On a cluster"). Submit with
#
#   sbatch --array=1-8 examples/cluster/slurm.sh          # 8 shards
#   python3 -c 'import polars as pl; print(pl.scan_parquet("part-*.parquet").collect())'
#
# HPC centres advise few, large shards: beyond about ten jobs a minute, run GNU parallel inside
# one allocation instead (examples/cluster/parallel.sh). Each shard is a table by itself (its
# own schema and header), so a glob reads them together, and the shards of any N together are
# exactly the rows of the unsharded sweep, in order (tests/suite/sweeps.rs checks it for GNU
# parallel; this script is the same command under Slurm's array variables).
#SBATCH --job-name=collide-sweep
#SBATCH --ntasks=1
#SBATCH --cpus-per-task=2
#SBATCH --output=collide-sweep-%a.log
set -euo pipefail
COLLIDE=${COLLIDE:-collide}
K=${SLURM_ARRAY_TASK_ID:?run under sbatch --array}
N=${SLURM_ARRAY_TASK_COUNT:?run under sbatch --array}
# The sweep: restitution of a Hertz contact against impact speed and stiffness.
"$COLLIDE" contact -m 1,1 -x 0,1 --sizes 1,1 -v 1,0 --law hertz \
    --vary v1=0.1:2:100:log --vary stiffness=10:1000:100:log \
    --shard "$K/$N" -o "part-$K.parquet"
