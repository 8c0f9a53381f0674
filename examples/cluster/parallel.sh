#!/usr/bin/env bash
# A sweep as SHARDS shards run by GNU parallel, JOBS at a time, then merged: the recipe of
# docs/sweeps.md ("On a cluster"), tested by tests/suite/sweeps.rs. Each shard is one process
# writing its own file with its own header (part-K.csv); the merge keeps the first header.
#
#   SHARDS=4 JOBS=2 bash examples/cluster/parallel.sh
#   # across hosts: add --sshlogin host1,host2 (and --transferfile/--return, or a shared disk)
#
# Environment: COLLIDE (the binary, default collide), SHARDS (default 4), JOBS (default: the
# cores here).
set -euo pipefail
COLLIDE=${COLLIDE:-collide}
SHARDS=${SHARDS:-4}
JOBS=${JOBS:-$(nproc)}
# The sweep: restitution of a linear contact against stiffness and damping ratio (40 runs).
SWEEP=(contact -m 1,1 -x 0,1 --sizes 1,1 -v 1,0 --vary stiffness=1,100 --vary zeta=0:0.9:20)

seq "$SHARDS" | parallel --will-cite -j "$JOBS" --halt now,fail=1 \
    "$COLLIDE" "${SWEEP[@]}" --shard "{}/$SHARDS" -o "part-{}.csv"

# The merge: the first shard's header, then every shard's rows in order. With Polars instead:
#   pl.read_csv("part-*.csv")  (each part is a table by itself), or for Parquet parts
#   pl.scan_parquet("part-*.parquet").collect()
{
    head -n 1 part-1.csv
    for k in $(seq "$SHARDS"); do tail -n +2 "part-$k.csv"; done
} >merged.csv
