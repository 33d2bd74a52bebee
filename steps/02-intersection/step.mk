# Step 02's manifest: what the build, the image test, the traces, the
# report and the grader know of the step (docs/instructors.md, "A step's
# manifest"). KEY = value, one line each; `make regen` after a change.

# The Step fields of main.c (build/gen/02-intersection/step_manifest.h): the --help line
# (\n: a line break), the scene features it renders (SceneFeature bits), the
# default sampler and --adaptive threshold (empty, 0: none).
SUMMARY  = Step 02: ray-object intersection through a fixed camera. Left half:\nnormals as colours; right half: distance as grey.
FEATURES =
SAMPLER  =
ADAPTIVE = 0

# The default scene, compiled into the program.
SCENE = scenes/spheres.scene
# The unit tests, tests/test_NAME.c, that make test-step 2 runs.
# (SHAPES: the own test of every shape of the registry, common/shapes.h.)
TESTS = ray SHAPES scene vec bounds shapes

# The reference image images/02-intersection.png: the default scene at WIDTH HEIGHT with
# these options (besides --threads 2 --quiet); the Phong terms drawn alone
# (images/02-intersection.TERM.png); the image test's tolerance: TOL FRACTION MAX (a
# channel may be off by TOL/255 in at most FRACTION of the channels, never
# by more than MAX/255; tests/image_test.c).
IMAGE_SIZE  = 320 240
IMAGE_ARGS  =
IMAGE_TERMS =
IMAGE_TOL   = 1.5 0.001 16

# The reference traces (make trace-step 2 X Y), a file per pixel in
# tests/traces/02-intersection/: TRACE_X_Y = [more options] | what the pixel shows,
# as its trace shows it (X from the left, Y from the top), each rendered with
# TRACE_ARGS.
TRACE_ARGS = --width 320 --height 240
TRACE_47_150 = | the green sphere one pixel inside its silhouette: its normal as colour
TRACE_230_160 = | the right half: the white sphere's distance t as grey
TRACE_100_50 = | a ray that hits nothing: the background
TRACE_60_120 = --scene tests/traces/back-face.scene | a wall seen from behind: backface = yes, the normal flipped toward the ray
