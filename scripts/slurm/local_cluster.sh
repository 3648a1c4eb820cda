#!/usr/bin/env bash
# A single-node Slurm cluster started on this machine, and a sharded sweep run on it end to
# end with scripts/slurm/submit.sh: `bash scripts/slurm/local_cluster.sh` (as root).
#
# 1. Installs Debian's slurm-wlm and munge with apt-get when missing.
# 2. Starts munged (its own key and socket) and slurmctld + slurmd from a minimal slurm.conf
#    (this host, CPUs=2, proctrack/linuxproc, no cgroups, no accounting) in a fresh directory
#    under /tmp, and waits for the node to be idle.
# 3. Runs two sweeps as a job array + a dependent merge job and checks that every merged file
#    is byte for byte the unsharded run's (cmp): a theory-only Popov map (192 points, 7 tasks)
#    and a feeder map in rapier worlds (4 points, 3 tasks). Then the rerun of a failed task:
#    one Popov shard is deleted, `stickslip sweep merge` names it, `submit.sh -a 3` reruns
#    only that task and the merge is again the unsharded run. Last, a sweep whose tasks fail:
#    its merge job is cancelled and submit.sh -w says so.
# 4. Stops the daemons it started (scontrol shutdown, munged by its pid), also on failure.
#
# STICKSLIP: the binary to use (default: the CLI built in the test profile and the selection of
# scripts/cargo_selection.sh, which reuses the build of scripts/test.sh).
# KEEP=1 keeps the run directory (slurm.conf, logs, outputs) after a successful run.
# Timings are printed; startup (munged to an idle node) took well under a second here.
set -euo pipefail
cd "$(dirname "$0")/../.."
source scripts/cargo_selection.sh
now() { date +%s.%N; }
since() { awk -v a="$1" -v b="$(now)" 'BEGIN { printf "%.1f", b - a }'; }
t_all=$(now)

if ! command -v slurmctld >/dev/null || ! command -v slurmd >/dev/null ||
    ! command -v sbatch >/dev/null || ! command -v munged >/dev/null; then
    t=$(now)
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
        slurm-wlm munge >/dev/null
    echo "local_cluster: installed slurm-wlm and munge in $(since "$t") s"
fi

if [ -z "${STICKSLIP:-}" ]; then
    cargo build --workspace --profile test --features "$STICKSLIP_FEATURES" --bin stickslip
    STICKSLIP="$CARGO_TARGET_DIR/debug/stickslip"
fi
STICKSLIP=$(realpath "$STICKSLIP")

run=$(mktemp -d /tmp/stickslip-slurm.XXXXXX)
chmod 0755 "$run"
mkdir -p "$run/munge" "$run/ctld" "$run/slurmd" "$run/log"
export SLURM_CONF="$run/slurm.conf"
munged_pid='' ctld_pid='' slurmd_pid=''

# The pid a daemon wrote to file $1 (it appears shortly after the daemon forks).
pid_of() {
    for _ in $(seq 100); do
        [ -s "$1" ] && cat "$1" && return
        sleep 0.1
    done
    echo "local_cluster: no pid file $1" >&2
    return 1
}

stop() {
    local status=$? pid
    if [ -e "$run/slurmctld.pid" ] || [ -n "$ctld_pid" ]; then
        ctld_pid=${ctld_pid:-$(cat "$run/slurmctld.pid" 2>/dev/null || true)}
        slurmd_pid=${slurmd_pid:-$(cat "$run/slurmd.pid" 2>/dev/null || true)}
        scontrol shutdown >/dev/null 2>&1 || true
        for _ in $(seq 50); do
            alive=''
            for pid in $ctld_pid $slurmd_pid; do
                kill -0 "$pid" 2>/dev/null && alive=1
            done
            [ -z "$alive" ] && break
            sleep 0.2
        done
        for pid in $ctld_pid $slurmd_pid; do
            kill "$pid" 2>/dev/null || true
        done
    fi
    if [ -n "$munged_pid" ]; then
        kill "$munged_pid" 2>/dev/null || true
        for _ in $(seq 50); do
            kill -0 "$munged_pid" 2>/dev/null || break
            sleep 0.1
        done
    fi
    if [ "$status" -ne 0 ]; then
        echo "local_cluster: FAILED (logs in $run/log, $run/munge)" >&2
        tail -n 20 "$run"/log/*.log >&2 || true
    else
        echo "local_cluster: daemons stopped; total $(since "$t_all") s"
        [ -n "${KEEP:-}" ] || rm -rf "$run"
    fi
}
trap stop EXIT

# munged with its own key and socket (the system's munge, if any, is left alone).
t_up=$(now)
chown munge:munge "$run/munge"
chmod 0711 "$run/munge"
dd if=/dev/urandom of="$run/munge/munge.key" bs=1024 count=1 status=none
chown munge:munge "$run/munge/munge.key"
chmod 0400 "$run/munge/munge.key"
runuser -u munge -- /usr/sbin/munged --key-file="$run/munge/munge.key" \
    --socket="$run/munge/munge.socket" --pid-file="$run/munge/munged.pid" \
    --log-file="$run/munge/munged.log" --seed-file="$run/munge/munged.seed"
munged_pid=$(pid_of "$run/munge/munged.pid")

host=$(hostname -s)
cat >"$SLURM_CONF" <<EOF
ClusterName=stickslip
SlurmctldHost=$host
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$run/munge/munge.socket
StateSaveLocation=$run/ctld
SlurmdSpoolDir=$run/slurmd
SlurmctldPidFile=$run/slurmctld.pid
SlurmdPidFile=$run/slurmd.pid
SlurmctldLogFile=$run/log/slurmctld.log
SlurmdLogFile=$run/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MpiDefault=none
ReturnToService=2
MailProg=/bin/true
MinJobAge=600
NodeName=$host CPUs=2 State=UNKNOWN
PartitionName=local Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
slurmctld -f "$SLURM_CONF"
ctld_pid=$(pid_of "$run/slurmctld.pid")
slurmd -f "$SLURM_CONF"
slurmd_pid=$(pid_of "$run/slurmd.pid")
state=''
for _ in $(seq 240); do
    state=$(sinfo -h -o %T 2>/dev/null || true)
    [ "$state" = idle ] && break
    sleep 0.5
done
[ "$state" = idle ] || {
    echo "local_cluster: the node is '$state' after 120 s" >&2
    exit 1
}
echo "local_cluster: Slurm up ($(sinfo -h -o '%P %D node %N, %c CPUs, %T')) in $(since "$t_up") s"

# Every file of the unsharded run $1 is in the merged output $2 with the same bytes.
same_files() {
    local whole=$1 merged=$2 f n=0
    for f in "$whole"/*; do
        cmp "$f" "$merged/$(basename "$f")"
        n=$((n + 1))
    done
    echo "local_cluster: cmp: all $n files of $(basename "$merged") equal the unsharded run's"
}

# $1 kind, $2 shards, then the sweep's options.
sweep() {
    local kind=$1 shards=$2 t
    shift 2
    "$STICKSLIP" sweep "$kind" "$@" --threads 2 --out "$run/whole-$kind" >/dev/null
    t=$(now)
    bash scripts/slurm/submit.sh -w -n "$shards" -b "$STICKSLIP" "$run/out-$kind" "$kind" "$@"
    echo "local_cluster: $kind: $shards tasks and the merge in $(since "$t") s"
    same_files "$run/whole-$kind" "$run/out-$kind"
}

popov=(--theory-only --beta 0.5:12:12 --alpha 0.2:0.8:4)
sweep popov 7 "${popov[@]}"
sweep feeder 3 --amplitude 1:1.5:2 --frequency 25 --angle 20:30:2 --law plain --periods 2:2

# A failed task: its shard is missing, the merge says which task to rerun, and the rerun of
# that task alone (plus a new merge) completes the sweep.
rm "$run/out-popov/shards/popov.shard-3-of-7".* "$run/out-popov"/popov*
if "$STICKSLIP" sweep merge "$run/out-popov/shards" --out "$run/out-popov" 2>"$run/merge.err"; then
    echo "local_cluster: the merge of 6 of 7 shards succeeded" >&2
    exit 1
fi
grep -q -- '--array=3)' "$run/merge.err"
echo "local_cluster: without shard 3: $(cat "$run/merge.err")"
bash scripts/slurm/submit.sh -w -n 7 -a 3 -b "$STICKSLIP" "$run/out-popov" popov "${popov[@]}"
same_files "$run/whole-popov" "$run/out-popov"

# Failing tasks (a β out of the domain): the merge job is cancelled and `submit.sh -w` fails.
if bash scripts/slurm/submit.sh -w -n 2 -b "$STICKSLIP" "$run/out-bad" popov --beta 0:1:3 \
    2>"$run/submit.err"; then
    echo "local_cluster: a sweep of failing tasks was merged" >&2
    exit 1
fi
grep -q 'ended CANCELLED' "$run/submit.err"
grep -q -- '--beta' "$run/out-bad/logs/"sweep-*_1.out
echo "local_cluster: failing tasks: $(cat "$run/submit.err")"
