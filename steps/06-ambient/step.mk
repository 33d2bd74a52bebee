# Step 06's manifest: what the build, the image test, the traces, the
# report and the grader know of the step (docs/instructors.md, "A step's
# manifest"). KEY = value, one line each; `make regen` after a change.

# The Step fields of main.c (build/gen/06-ambient/step_manifest.h): the --help line
# (\n: a line break), the scene features it renders (SceneFeature bits), the
# default sampler and --adaptive threshold (empty, 0: none).
SUMMARY  = Step 06: ambient light, and point lights the camera sees.
FEATURES = SCENE_CAMERA | SCENE_LIGHTS | SCENE_SHADOWS | SCENE_AMBIENT | SCENE_LIGHT_SHAPES
SAMPLER  =
ADAPTIVE = 0

# The default scene, compiled into the program.
SCENE = scenes/ambient.scene
# The unit tests, tests/test_NAME.c, that make test-step 6 runs.
TESTS = ambient

# The reference image images/06-ambient.png: the default scene at WIDTH HEIGHT with
# these options (besides --threads 2 --quiet); the Phong terms drawn alone
# (images/06-ambient.TERM.png); the image test's tolerance: TOL FRACTION MAX (a
# channel may be off by TOL/255 in at most FRACTION of the channels, never
# by more than MAX/255; tests/image_test.c).
IMAGE_SIZE  = 320 240
IMAGE_ARGS  =
IMAGE_TERMS = ambient diffuse specular
IMAGE_TOL   = 1.5 0.001 16

# The reference traces (make trace-step 6 X Y), a file per pixel in
# tests/traces/06-ambient/: TRACE_X_Y = [more options] | what the pixel shows,
# as its trace shows it (X from the left, Y from the top), each rendered with
# TRACE_ARGS.
TRACE_ARGS = --width 320 --height 240
TRACE_277_14 = | the point light's own sphere: P / t^2
TRACE_210_170 = | inside the white sphere's shadow: the ambient term alone
TRACE_171_99 = | the red sphere's highlight, with the ambient term
