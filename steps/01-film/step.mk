# Step 01's manifest: what the build, the image test, the traces, the
# report and the grader know of the step (docs/instructors.md, "A step's
# manifest"). KEY = value, one line each; `make regen` after a change.

# The Step fields of main.c (build/gen/01-film/step_manifest.h): the --help line
# (\n: a line break), the scene features it renders (SceneFeature bits), the
# default sampler and --adaptive threshold (empty, 0: none).
SUMMARY  = Step 01: the film. Four quadrants, red bottom left, green top left,\nblue bottom right, white top right (256x128 by default).
FEATURES =
SAMPLER  =
ADAPTIVE = 0

# The default scene, compiled into the program.
SCENE = scenes/film.scene
# The unit tests, tests/test_NAME.c, that make test-step 1 runs.
TESTS = film export image

# The reference image images/01-film.png: the default scene at WIDTH HEIGHT with
# these options (besides --threads 2 --quiet); the Phong terms drawn alone
# (images/01-film.TERM.png); the image test's tolerance: TOL FRACTION MAX (a
# channel may be off by TOL/255 in at most FRACTION of the channels, never
# by more than MAX/255; tests/image_test.c).
IMAGE_SIZE  = 256 128
IMAGE_ARGS  =
IMAGE_TERMS =
IMAGE_TOL   = 1.5 0.001 16

# The reference traces (make trace-step 1 X Y), a file per pixel in
# tests/traces/01-film/: TRACE_X_Y = [more options] | what the pixel shows,
# as its trace shows it (X from the left, Y from the top), each rendered with
# TRACE_ARGS.
TRACE_ARGS =
TRACE_10_10 = | the top left quadrant: green (j counts from the bottom)
TRACE_200_100 = | the bottom right quadrant: blue
