# Step 03's manifest: what the build, the image test, the traces, the
# report and the grader know of the step (docs/instructors.md, "A step's
# manifest"). KEY = value, one line each; `make regen` after a change.

# The Step fields of main.c (build/gen/03-camera/step_manifest.h): the --help line
# (\n: a line break), the scene features it renders (SceneFeature bits), the
# default sampler and --adaptive threshold (empty, 0: none).
SUMMARY  = Step 03: the lookAt pinhole camera; objects in flat colours.
FEATURES = SCENE_CAMERA
SAMPLER  =
ADAPTIVE = 0

# The default scene, compiled into the program.
SCENE = scenes/spheres.scene
# The unit tests, tests/test_NAME.c, that make test-step 3 runs.
TESTS = camera parser cli

# The reference image images/03-camera.png: the default scene at WIDTH HEIGHT with
# these options (besides --threads 2 --quiet); the Phong terms drawn alone
# (images/03-camera.TERM.png); the image test's tolerance: TOL FRACTION MAX (a
# channel may be off by TOL/255 in at most FRACTION of the channels, never
# by more than MAX/255; tests/image_test.c).
IMAGE_SIZE  = 320 240
IMAGE_ARGS  =
IMAGE_TERMS =
IMAGE_TOL   = 1.5 0.001 16

# The reference traces (make trace-step 3 X Y), a file per pixel in
# tests/traces/03-camera/: TRACE_X_Y = [more options] | what the pixel shows,
# as its trace shows it (X from the left, Y from the top), each rendered with
# TRACE_ARGS.
TRACE_ARGS = --width 320 --height 240
TRACE_127_100 = | the red sphere one pixel inside its left silhouette
TRACE_160_110 = | the red sphere facing the camera
TRACE_60_210 = | the floor near the camera
