# Step 05's manifest: what the build, the image test, the traces, the
# report and the grader know of the step (docs/instructors.md, "A step's
# manifest"). KEY = value, one line each; `make regen` after a change.

# The Step fields of main.c (build/gen/05-shadows/step_manifest.h): the --help line
# (\n: a line break), the scene features it renders (SceneFeature bits), the
# default sampler and --adaptive threshold (empty, 0: none).
SUMMARY  = Step 05: Phong shading with shadows (any-hit shadow rays).
FEATURES = SCENE_CAMERA | SCENE_LIGHTS | SCENE_SHADOWS
SAMPLER  =
ADAPTIVE = 0

# The default scene, compiled into the program.
SCENE = scenes/spheres.scene
# The unit tests, tests/test_NAME.c, that make test-step 5 runs.
TESTS = shadows shadows_lecture

# The reference image images/05-shadows.png: the default scene at WIDTH HEIGHT with
# these options (besides --threads 2 --quiet); the Phong terms drawn alone
# (images/05-shadows.TERM.png); the image test's tolerance: TOL FRACTION MAX (a
# channel may be off by TOL/255 in at most FRACTION of the channels, never
# by more than MAX/255; tests/image_test.c).
IMAGE_SIZE  = 320 240
IMAGE_ARGS  =
IMAGE_TERMS = ambient diffuse specular
IMAGE_TOL   = 1.5 0.001 16

# The reference traces (make trace-step 5 X Y), a file per pixel in
# tests/traces/05-shadows/: TRACE_X_Y = [more options] | what the pixel shows,
# as its trace shows it (X from the left, Y from the top), each rendered with
# TRACE_ARGS.
TRACE_ARGS = --width 320 --height 240
TRACE_155_80 = | the top of the red sphere, lit by both lights: its shadow rays must not hit the sphere they start on
TRACE_197_170 = | the floor just outside the white sphere's shadow: both shadow rays clear
TRACE_200_170 = | the shadow's edge: the point light's shadow ray blocked, the directional one clear
TRACE_210_170 = | inside the shadow: both shadow rays blocked
