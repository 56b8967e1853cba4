#!/bin/sh
# One render-farm task: one chunk of a shot, as the whole shot's run renders it (rmfx render
# --frame-range with --preroll, docs/sequences.md). Task k writes frames FIRST + k·CHUNK onwards,
# CHUNK of them (fewer at the end); each file is written whole or not at all, so a task that is
# killed and run again leaves no half frame. Slurm's job arrays set SLURM_ARRAY_TASK_ID
# (samples/farm/slurm-array.sbatch); any other manager can set TASK instead.
#
#   WORKSPACE  the effect workspace            INPUT   the shot, e.g. shot/beauty.%04d.exr
#   OUTPUT     the frames written, a pattern   FIRST, LAST  the shot's frame numbers
#   CHUNK      frames a task (default 12)      PREROLL warm-up frames (default 0)
#   FPS        frames per second (default 24)  RMFX    the rmfx command (default: rmfx on PATH)
# Arguments after the script's go to rmfx render (--set Exposure_Level=1.2, --size 1920x1080, …).
set -eu
task=${SLURM_ARRAY_TASK_ID:-${TASK:?set TASK (or SLURM_ARRAY_TASK_ID) to the task number, from 0}}
: "${WORKSPACE:?set WORKSPACE}" "${INPUT:?set INPUT (a frame pattern)}" "${OUTPUT:?set OUTPUT (a frame pattern)}"
: "${FIRST:?set FIRST, the shot's first frame number}" "${LAST:?set LAST, its last}"
chunk=${CHUNK:-12} preroll=${PREROLL:-0} fps=${FPS:-24} rmfx=${RMFX:-rmfx}
start=$((FIRST + task * chunk))
if [ "$start" -gt "$LAST" ]; then
  echo "task $task: nothing to render (frames $FIRST-$LAST, $chunk a task: tasks 0-$(((LAST - FIRST) / chunk)))"
  exit 0
fi
end=$((start + chunk - 1))
[ "$end" -le "$LAST" ] || end=$LAST
echo "task $task: frames $start-$end of $FIRST-$LAST, $preroll frames of warm-up"
exec "$rmfx" render "$WORKSPACE" --input "$INPUT" -o "$OUTPUT" --fps "$fps" --preroll "$preroll" --frame-range "$start-$end" "$@"
