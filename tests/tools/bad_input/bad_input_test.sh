#!/usr/bin/env bash
# The bad-input matrix of docs/reliability.md: houghloc-offline, houghloc-fieldmap and
# houghloc-render on broken inputs, in groups that ctest runs as separate tests
# (bad_input_matrix.<group>). Each case asserts the exit status (0 where the run goes on,
# non-zero where it cannot), a message naming the file, line or key, no signal, no hang (60 s
# timeout; a process still there 10 s after its SIGTERM is killed and counts as a hang) and no
# NaN or infinity in any output file. The node group runs houghloc-node's command line (over
# memq://: no network); a node that must go on running is stopped after 8 s.
#   bad_input_test.sh render BASE_FOLDER RENDER       (the good 6-frame recording, once)
#   bad_input_test.sh GROUP BASE_FOLDER WORK_FOLDER OFFLINE FIELDMAP RENDER SPL_JSON [NODE]
# GROUP: images, camera, recordings, maps_options or node.
set -uo pipefail
GROUP=$1 BASE=$2
if [[ $GROUP == render ]]; then
  rm -rf "$BASE" && exec "$3" --standard spl --camera nao-top --trajectory walk --frames 6 --seed 3 -q -o "$BASE"
fi
WORK=$3 OFFLINE=$4 FIELDMAP=$5 RENDER=$6 SPL_JSON=$7 NODE=${8:-}
[[ -f $BASE/frames.csv ]] || { echo "no recording in $BASE (run the render step first)"; exit 1; }
rm -rf "$WORK" && mkdir -p "$WORK" && cd "$WORK" || exit 1
failures=0
cases=0

# check NAME EXPECT(0|fail|running) MESSAGE COMMAND...: runs COMMAND, checks status and stderr
# (running: a process that serves until stopped, still running after 8 s).
check() {
  local name=$1 expect=$2 message=$3
  shift 3
  cases=$((cases + 1))
  local start=$SECONDS
  timeout -k 10 "$([[ $expect == running ]] && echo 8 || echo 60)" "$@" >"$name.out" 2>"$name.err"
  local rc=$? problem="" seconds=$((SECONDS - start))
  if ((rc == 137)); then
    problem="still running 10 s after SIGTERM (killed)"
  elif [[ $expect == running ]]; then
    ((rc == 124)) || problem="exit $rc, expected to go on running"
    rc=0
  fi
  if [[ -n $problem ]]; then
    :
  elif ((rc == 124)); then
    problem="hang (timeout)"
  elif ((rc > 128)); then
    problem="signal $((rc - 128))"
  elif [[ $expect == 0 && $rc != 0 ]]; then
    problem="exit $rc, expected 0"
  elif [[ $expect == fail && $rc == 0 ]]; then
    problem="exit 0, expected non-zero"
  elif [[ -n $message ]] && ! grep -qF -- "$message" "$name.err"; then
    problem="stderr lacks '$message'"
  elif [[ -d c/out ]] && grep -rqiwE "nan|-?inf(inity)?" --include='*.csv' --include='*.json' c/out; then
    problem="NaN or infinity in an output file"
  fi
  if [[ -n $problem ]]; then
    failures=$((failures + 1))
    echo "FAIL $name (${seconds} s): $problem; stderr: $(head -c 400 "$name.err")"
  else
    echo "ok   $name (${seconds} s, exit $rc): $(grep -F -- "$message" "$name.err" | head -n 1 | cut -c1-160)"
  fi
}
# fresh copy of the good recording in c/
copy() { rm -rf c && cp -r "$BASE" c; }
offline() { check "$1" "$2" "$3" "$OFFLINE" c --standard spl --quiet -o c/out "${@:4}"; }

images() {
  # Images: one bad image among the frames is skipped with a warning naming it (policy, docs).
  copy; : >c/images/000002.jpg
  offline zero_byte_image 0 "c/images/000002.jpg: image unreadable, frame skipped"
  copy; head -c 300 "$BASE"/images/000002.jpg >c/images/000002.jpg
  offline truncated_image 0 "c/images/000002.jpg"
  copy; echo "not an image" >c/images/000002.jpg
  offline text_as_image 0 "c/images/000002.jpg: image unreadable, frame skipped"
  offline text_as_image_learning_tilt 0 "c/images/000002.jpg: image unreadable, frame skipped" \
    --global-only --learn-tilt-first
  copy; rm c/images/000002.jpg
  offline missing_image 0 "c/images/000002.jpg"
  copy; "$RENDER" --standard spl --camera kid-wide --trajectory walk --frames 1 -q -o other >/dev/null
  cp other/images/000000.jpg c/images/000002.jpg
  offline image_of_other_size fail "c/images/000002.jpg: image is"
  offline image_of_other_size_learning_tilt fail "c/images/000002.jpg: image is" --learn-tilt-first
}

camera() {
  # camera.yaml
  copy; sed -i '/image_width/d' c/camera.yaml
  offline camera_missing_key fail "c/camera.yaml: key 'image_width': missing"
  copy; sed -i 's/data: \[ [0-9.]*, 0\., /data: [ -598., 0., /' c/camera.yaml
  offline camera_negative_focal fail "c/camera.yaml: key 'camera_matrix'"
  copy; sed -i 's/data: \[ [0-9.]*, 0\., /data: [ 0., 0., /' c/camera.yaml
  offline camera_singular_matrix fail "c/camera.yaml: key 'camera_matrix'"
  copy; python3 - <<'PY'
p = "c/camera.yaml"
s = open(p).read()
i = s.rfind("distortion_coefficients")
open(p, "w").write(s[:i] + "distortion_coefficients: [ 0.1, 0.2, 0.3 ]\nmodel: pinhole\n")
PY
  offline distortion_wrong_length fail "c/camera.yaml: key 'distortion_coefficients'"
  copy; printf ' c: 1\n-x\n-' >c/camera.yaml
  offline camera_bad_indentation fail "c/camera.yaml: line 2: indented less than the first key"
}

# bad_numbers FILE FIRST_COLUMN "NAMES" "VALUES": one case per value in each named column (from
# FIRST_COLUMN on, 1-based) of row 3 of the recording's FILE; the run must stop naming them.
bad_numbers() {
  local file=$1 col=$2 name bad
  for name in $3; do
    for bad in $4; do
      copy; awk -F, -v OFS=, -v c="$col" -v v="$bad" 'NR == 3 { $c = v } { print }' "$BASE/$file" >"c/$file"
      offline "${file%.csv}_${name}_$bad" fail "c/$file:3: column '$name': '$bad' is not a finite number"
    done
    col=$((col + 1))
  done
}

recordings() {
  # frames.csv, groundtruth.csv, hints.csv
  copy; sed -i '3s/,[^,]*$//' c/frames.csv
  offline csv_missing_column fail "c/frames.csv:3: malformed row"
  copy; sed -i '3s/$/,,/' c/frames.csv
  offline csv_extra_commas fail "c/frames.csv:3: malformed row"
  copy; sed -i '1s/odom_x/odom_q/' c/frames.csv
  offline csv_missing_header_column fail "column 'odom_x'"
  copy; sed -i '3s/^\([^,]*,[^,]*\),[^,]*,/\1,abc,/' c/frames.csv
  offline csv_text_in_number fail "c/frames.csv:3: column 'odom_x': 'abc' is not a finite number"
  copy; awk -F, -v OFS=, 'NR == 3 { $4 = "" } { print }' "$BASE"/frames.csv >c/frames.csv
  offline frames_odometry_partly_empty fail "c/frames.csv:3: column 'odom_y' is empty"
  bad_numbers frames.csv 3 "odom_x odom_y odom_theta cam_x cam_y cam_z cam_roll cam_pitch cam_yaw" \
    "nan inf -inf 1e309"
  copy; awk -F, -v OFS=, 'NR == 3 { $2 = "12.5" } { print }' "$BASE"/frames.csv >c/frames.csv
  offline frames_fractional_time fail "c/frames.csv:3: column 't_us'"
  copy; awk -F, -v OFS=, 'NR == 3 { $2 = "99999999999999999999" } { print }' "$BASE"/frames.csv >c/frames.csv
  offline frames_time_overflow fail "c/frames.csv:3: column 't_us'"
  copy; awk -F, -v OFS=, 'NR == 4 { $2 = "1" } { print }' "$BASE"/frames.csv >c/frames.csv
  offline frames_time_backwards fail "c/frames.csv:4: t_us goes backwards"
  # One camera repeating a time (a clock glitch): both frames run, poses.csv keeps one row per time.
  copy; awk -F, -v OFS=, 'NR == 3 { t = $2 } NR == 4 { $2 = t } { print }' "$BASE"/frames.csv >c/frames.csv
  offline frames_time_repeated 0 ""
  bad_numbers groundtruth.csv 2 "x y theta" "nan inf 1e309"
  copy; sed -i '3p' c/groundtruth.csv
  offline groundtruth_duplicate_time fail "c/groundtruth.csv:4: t_us repeats"
  copy; printf 't_us,kind,x,y,theta,sigma_x,sigma_y,sigma_theta\n0,RESET_TO,1,0,0,0.1,0.1,nan\n' >c/hints.csv
  offline hints_nan fail "c/hints.csv:2: column 'sigma_theta'"
  copy; printf 't_us,kind,x,y,theta,sigma_x,sigma_y,sigma_theta\n0,TELEPORT,1,0,0,0.1,0.1,0.1\n' >c/hints.csv
  offline hints_unknown_kind fail "c/hints.csv:2"
  copy; printf 't_us,kind,x,y,theta,sigma_x,sigma_y,sigma_theta\n33333,ADD,1,0,0,0.1,0.1,0.1\n33333,ADD,-1,0,3.1,0.1,0.1,0.1\n' >c/hints.csv
  offline hints_repeated_time_for_two_poses 0 ""
  copy; printf 't_us,kind,x,y,theta,sigma_x,sigma_y,sigma_theta\n66667,ADD,1,0,0,0.1,0.1,0.1\n33333,ADD,-1,0,3.1,0.1,0.1,0.1\n' >c/hints.csv
  offline hints_time_backwards fail "c/hints.csv:3: t_us goes backwards"
}

# The broken maps and config files that the maps_options and node groups give the tools.
bad_maps() {
  printf '%%YAML:1.0\n---\n' >empty.yaml
  "$FIELDMAP" new --standard spl -o spl.yaml >/dev/null
  python3 - <<'PY'
s = open("spl.yaml").read()
j = s.find("[", s.find("segments:"))
k = s.find("]", j)
open("zero_segment.yaml", "w").write(s[:j + 1] + " 1.0, 2.0, 1.0, 2.0 " + s[k:])
PY
  printf 'vision:\n  bogus_key: 1\n' >bad_config.yaml
}

maps_options() {
  bad_maps
  copy
  check offline_empty_map fail "empty.yaml" "$OFFLINE" c --field empty.yaml --quiet -o c/out
  check fieldmap_zero_length_segment fail "zero_segment.yaml: segments[0]: zero length" "$FIELDMAP" validate zero_segment.yaml
  check offline_zero_length_segment fail "zero_segment.yaml" "$OFFLINE" c --field zero_segment.yaml --quiet -o c/out
  check fieldmap_empty_map fail "empty.yaml" "$FIELDMAP" validate empty.yaml
  check fieldmap_missing_map fail "/nonexistent/field.yaml" "$FIELDMAP" validate /nonexistent/field.yaml
  sed 's/"lineWidth": *[0-9.]*/"lineWidth": 1e309/' "$SPL_JSON" >overflow.json
  check spl_number_overflow fail "overflow.json: invalid JSON after key 'lineWidth': number overflow" "$FIELDMAP" import-spl overflow.json -o x.yaml
  sed 's/"length": *[0-9.]*/"length": 0.5/' "$SPL_JSON" >contradictory.json
  check spl_contradictory_dimensions fail "contradictory.json: field.length" "$FIELDMAP" import-spl contradictory.json -o x.yaml
  sed 's/"lineWidth"/"lineWidht"/' "$SPL_JSON" >unknown_key.json
  check spl_unknown_key fail "unknown_key.json: field.lineWidht" "$FIELDMAP" import-spl unknown_key.json -o x.yaml
  copy
  check offline_unknown_standard fail "--standard" "$OFFLINE" c --standard spl2030 --quiet -o c/out
  check fieldmap_unknown_standard fail "--standard" "$FIELDMAP" new --standard spl2030 -o x.yaml
  offline unknown_config_key fail "bad_config.yaml: vision.bogus_key: unknown key" --config bad_config.yaml
  check offline_missing_folder fail "/nonexistent/recording" "$OFFLINE" /nonexistent/recording --standard spl --quiet -o c/out
  check unwritable_output_folder fail "/proc/houghloc-out" "$OFFLINE" c --standard spl --quiet -o /proc/houghloc-out
  check render_unwritable_output fail "/proc/houghloc-out" "$RENDER" --standard spl --camera nao-top --frames 1 -q -o /proc/houghloc-out
  printf 'fps: 30\nframs: 10\n' >typo.yaml
  check render_unknown_scenario_key fail "typo.yaml: frams: unknown key" "$RENDER" --scenario typo.yaml -q -o r
  printf 'fps: 30\n  frames: -5\n' >negative.yaml
  check render_bad_scenario fail "negative.yaml" "$RENDER" --scenario negative.yaml -q -o r

  # A full disk: a 64 kB tmpfs (needs root for the mount).
  if [[ $(id -u) -eq 0 ]] && mkdir -p full && mount -t tmpfs -o size=64k tmpfs full 2>/dev/null; then
    copy
    check offline_disk_full fail "full/out/" "$OFFLINE" c --standard spl --quiet --points -o full/out
    check render_disk_full fail "full/r" "$RENDER" --standard spl --camera nao-top --frames 5 -q -o full/r
    umount full
  else
    echo "skip disk_full: not root or tmpfs mount refused (run the test as root to include it)"
  fi
}

# houghloc-node's command line: every problem before it serves names the file, key or flag.
node_command_line() {
  [[ -n $NODE ]] || { echo "no houghloc-node given"; return 1; }
  node() { check "$1" "$2" "$3" "$NODE" --lcm-url memq:// "${@:4}"; }
  bad_maps
  copy
  node node_missing_map fail "/nonexistent/field.yaml" --field /nonexistent/field.yaml --camera-yaml c/camera.yaml
  node node_empty_map fail "empty.yaml" --field empty.yaml --camera-yaml c/camera.yaml
  node node_zero_length_segment fail "zero_segment.yaml: segments[0]: zero length" --field zero_segment.yaml --camera-yaml c/camera.yaml
  node node_unknown_standard fail "--standard: unknown standard field 'spl2030'" --standard spl2030 --camera-yaml c/camera.yaml
  node node_no_camera fail "--camera-yaml" --standard spl
  node node_missing_camera_file fail "/nonexistent/camera.yaml" --standard spl --camera-yaml /nonexistent/camera.yaml
  copy; sed -i '/image_width/d' c/camera.yaml
  node node_camera_missing_key fail "c/camera.yaml: key 'image_width': missing" --standard spl --camera-yaml c/camera.yaml
  copy
  node node_unknown_config_key fail "bad_config.yaml: vision.bogus_key: unknown key" --standard spl --camera-yaml c/camera.yaml --config bad_config.yaml
  printf 'node:\n  lcm_urll: memq://\n' >bad_node_config.yaml
  node node_unknown_node_key fail "bad_node_config.yaml: node.lcm_urll: unknown key" --standard spl --camera-yaml c/camera.yaml --config bad_node_config.yaml
  node node_bad_log_level fail "--log-level: expected error, warn, info or debug, not 'loud'" --standard spl --camera-yaml c/camera.yaml --log-level loud
  node node_bad_line_points fail "--publish-line-points: expected on or off" --standard spl --camera-yaml c/camera.yaml --publish-line-points yes
  node node_device_without_id fail "'/dev/video99': expected ID=VALUE" --standard spl --camera-yaml c/camera.yaml --device /dev/video99
  node node_device_of_unknown_camera fail "no --camera-yaml for camera 'top'" --standard spl --camera-yaml c/camera.yaml --device top=/dev/video99
  check node_bad_lcm_url fail "cannot open LCM URL 'bogus://x'" "$NODE" --standard spl --camera-yaml c/camera.yaml --lcm-url bogus://x
  # The node's own state file, corrupt: reported and ignored, the node serves (docs/node.md).
  printf 'x: 1.0\ny: [oops\n' >corrupt_pose.yaml
  node node_corrupt_saved_pose running "corrupt_pose.yaml" --standard spl --camera-yaml c/camera.yaml --save-pose corrupt_pose.yaml
  printf 'x: 1.0\ny: 2.0\n' >partial_pose.yaml
  node node_saved_pose_missing_key running "partial_pose.yaml: theta: missing; starting without a saved pose" --standard spl --camera-yaml c/camera.yaml --save-pose partial_pose.yaml
}

case $GROUP in
  images | camera | recordings | maps_options) "$GROUP" ;;
  node) node_command_line || failures=$((failures + 1)) ;;
  *) echo "unknown group '$GROUP'"; exit 1 ;;
esac
echo "$GROUP: $cases cases, $failures failed, $SECONDS s"
((failures == 0))
