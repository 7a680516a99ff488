#!/usr/bin/env bash
# A single-node Slurm on this machine, to test `cairn sweep --scheduler slurm` for real: brings up
# munged, slurmctld and slurmd with a private slurm.conf (nothing is written under /etc), submits a
# small sweep as a job array with its merge job, waits, and checks that the merged table equals the
# one of the same sweep run locally. Stops the daemons it started.
#
#   bash scripts/slurm_local.sh [--no-install] CAIRN_EXE WORK_DIR [PLAN]   (WORK_DIR is emptied first)
#
# Needs root (the daemons). Without Slurm it installs Debian's slurmctld, slurmd, munge and
# slurm-client, unless --no-install: then it says so and exits 77 (ctest's "skipped").
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
install=1
if [[ "${1:-}" == "--no-install" ]]; then install=0; shift; fi
if (($# < 2)); then
  echo "usage: $0 [--no-install] CAIRN_EXE WORK_DIR [PLAN]" >&2
  exit 2
fi
cairn="$(realpath "$1")"
work="$(realpath -m "$2")"
plan="$(realpath "${3:-$here/scenarios/sweeps/column_small.toml}")"

skip() { echo "slurm_local: SKIPPED: $*" >&2; exit 77; }
if [[ $(id -u) -ne 0 ]]; then skip "needs root to start munged, slurmctld and slurmd"; fi
packages=(slurmctld slurmd munge slurm-client)
missing=()
for p in "${packages[@]}"; do
  [[ "$(dpkg-query -W -f='${db:Status-Abbrev}' "$p" 2>/dev/null)" == ii* ]] || missing+=("$p")
done
if ((${#missing[@]})); then
  ((install)) || skip "Slurm is not installed (missing ${missing[*]}; apt-get install ${packages[*]})"
  echo "slurm_local: installing ${missing[*]}" >&2
  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# a private configuration: every Slurm command below reads it through SLURM_CONF
conf_dir="$work/slurm"
rm -rf "$work"
mkdir -p "$conf_dir/state" "$conf_dir/spool" "$conf_dir/log"
export SLURM_CONF="$conf_dir/slurm.conf"
cpus=$(nproc)
cat > "$SLURM_CONF" <<CONF
ClusterName=cairntest
SlurmctldHost=localhost
SlurmUser=root
AuthType=auth/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
ReturnToService=2
MpiDefault=none
JobCompType=jobcomp/none
StateSaveLocation=$conf_dir/state
SlurmdSpoolDir=$conf_dir/spool
SlurmctldPidFile=$conf_dir/slurmctld.pid
SlurmdPidFile=$conf_dir/slurmd.pid
SlurmctldLogFile=$conf_dir/log/slurmctld.log
SlurmdLogFile=$conf_dir/log/slurmd.log
NodeName=localhost NodeHostname=localhost CPUs=$cpus RealMemory=1000 State=UNKNOWN
PartitionName=local Nodes=localhost Default=YES MaxTime=INFINITE State=UP
CONF

# munged (unless one runs already), then the controller and the node daemon
started_munge=0
if ! munge -n >/dev/null 2>&1; then
  mkdir -p /run/munge && chown munge:munge /run/munge
  runuser -u munge -- /usr/sbin/munged
  started_munge=1
fi
stop_all() {
  scontrol shutdown >/dev/null 2>&1 || true
  for f in "$conf_dir/slurmd.pid" "$conf_dir/slurmctld.pid"; do
    [[ -f "$f" ]] && kill "$(cat "$f")" 2>/dev/null || true
  done
  if ((started_munge)) && [[ -f /run/munge/munged.pid ]]; then kill "$(cat /run/munge/munged.pid)" 2>/dev/null || true; fi
}
trap stop_all EXIT
/usr/sbin/slurmctld -f "$SLURM_CONF"
/usr/sbin/slurmd -f "$SLURM_CONF" -N localhost
for _ in $(seq 60); do
  state=$(sinfo -h -N -o '%t' 2>/dev/null | head -1 || true)
  [[ "$state" == idle* || "$state" == mix* ]] && break
  sleep 1
done
[[ "$state" == idle* || "$state" == mix* ]] || { echo "slurm_local: the node did not come up (state '$state'); logs in $conf_dir/log" >&2; exit 1; }
echo "slurm_local: single-node Slurm up ($cpus CPUs)" >&2

# the same sweep: locally with 2 jobs, and as a job array of 3 tasks with its merge job
"$cairn" sweep "$plan" --out "$work/local" --jobs 2 --quiet
"$cairn" sweep "$plan" --out "$work/slurm_run" --scheduler slurm --tasks 3
merge_job=$(awk '$1 == "merge" {print $2}' "$work/slurm_run/slurm/jobs.txt")
for _ in $(seq 1800); do
  [[ -z "$(squeue -h -j "$merge_job" 2>/dev/null)" ]] && break
  sleep 1
done
merge_state=$(sacct -n -X -j "$merge_job" -o State 2>/dev/null | head -1 | tr -d ' ' || true)
if [[ ! -f "$work/slurm_run/runs.csv" ]]; then
  echo "slurm_local: FAILED: the merge job $merge_job wrote no runs.csv (state '$merge_state'); logs in $work/slurm_run/slurm" >&2
  exit 1
fi
status=0
for f in runs.csv fragility.csv report.md; do
  if [[ -f "$work/local/$f" ]] && ! cmp -s "$work/local/$f" "$work/slurm_run/$f"; then
    echo "slurm_local: FAILED: $f differs between the local run and the Slurm run" >&2
    diff "$work/local/$f" "$work/slurm_run/$f" | head -20 >&2
    status=1
  fi
done
tasks=$(ls "$work/slurm_run/slurm"/task-*.log | wc -l)
if ((status == 0)); then
  echo "slurm_local: passed: $(($(wc -l < "$work/local/runs.csv") - 1)) runs in $tasks array tasks, merged by job $merge_job: runs.csv, fragility.csv and report.md equal the local run's" >&2
fi
exit $status
