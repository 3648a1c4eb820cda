#!/usr/bin/env bash
# Submits a sharded stickslip sweep to Slurm: a job array of N tasks (sweep_task.sbatch, task K
# computes shard K/N into OUT/shards) and a merge job (merge.sbatch) that starts once every
# task has succeeded (--dependency=afterok) and writes the unsharded output into OUT.
#
#   scripts/slurm/submit.sh -n N [-a IDS] [-c CPUS] [-b STICKSLIP] [-w] OUT popov|feeder [OPTIONS...]
#
#   -n N          shards (array tasks); fixed for a sweep: reruns use the same N
#   -a IDS        tasks to run (default 1-N); e.g. -a 3,5 reruns only tasks 3 and 5
#   -c CPUS       cores per task (default 1), used as its --threads
#   -b STICKSLIP  the stickslip binary (default: `stickslip` on PATH); it and OUT must be on a
#                 file system every node sees
#   -w            wait for the merge job to end; exit 0 only if it completed
#   OPTIONS       the sweep's grid options (not --out, --shard or --threads)
#
# Other sbatch options come from sbatch's environment variables, e.g. SBATCH_PARTITION,
# SBATCH_ACCOUNT, SBATCH_TIMELIMIT. Logs: OUT/logs/sweep-JOB_TASK.out, OUT/logs/merge-JOB.out.
# If a task fails, the merge job is cancelled (--kill-on-invalid-dep); `stickslip sweep merge`
# names the missing tasks; rerun them with the same command and -a, which queues a new merge.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
usage() {
    sed -n '6,14p' "$0" >&2
    exit 2
}
shards='' array='' cpus=1 stickslip='' wait=''
while getopts 'n:a:c:b:wh' opt; do
    case $opt in
    n) shards=$OPTARG ;;
    a) array=$OPTARG ;;
    c) cpus=$OPTARG ;;
    b) stickslip=$OPTARG ;;
    w) wait=1 ;;
    *) usage ;;
    esac
done
shift $((OPTIND - 1))
[ -n "$shards" ] && [ $# -ge 2 ] || usage
out=$1
shift
stickslip=$(command -v "${stickslip:-stickslip}") || {
    echo "submit.sh: no stickslip binary (give one with -b)" >&2
    exit 2
}
stickslip=$(realpath "$stickslip")
mkdir -p "$out/shards" "$out/logs"
out=$(realpath "$out")
array=${array:-1-$shards}

job=$(sbatch --parsable --array="$array" --cpus-per-task="$cpus" \
    --output="$out/logs/sweep-%A_%a.out" \
    "$here/sweep_task.sbatch" "$stickslip" "$out" "$shards" "$@")
job=${job%%;*}
echo "sweep: array job $job, tasks $array of $shards -> $out/shards (logs in $out/logs)"
merge=(--parsable --dependency="afterok:$job" --kill-on-invalid-dep=yes
    --output="$out/logs/merge-%j.out")
script=("$here/merge.sbatch" "$stickslip" "$out")
merge_job=$(sbatch "${merge[@]}" "${script[@]}")
merge_job=${merge_job%%;*}
echo "merge: job $merge_job, after job $job -> $out"
[ -n "$wait" ] || exit 0
# Waits for the merge job's end (polling every 2 s: sbatch --wait backs off to half a minute).
while :; do
    state=$(scontrol show job "$merge_job" -o | grep -o 'JobState=[A-Z_]*' || true)
    state=${state#JobState=}
    case $state in
    COMPLETED)
        echo "merge: job $merge_job done"
        exit 0
        ;;
    PENDING | CONFIGURING | RUNNING | COMPLETING | SUSPENDED | REQUEUED | RESIZING) sleep 2 ;;
    *)
        echo "merge: job $merge_job ended ${state:-out of sight}: see $out/logs" >&2
        exit 1
        ;;
    esac
done
