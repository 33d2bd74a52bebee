# Step 04's manifest: what the build, the image test, the traces, the
# report and the grader know of the step (docs/instructors.md, "A step's
# manifest"). KEY = value, one line each; `make regen` after a change.

# The Step fields of main.c (build/gen/04-phong/step_manifest.h): the --help line
# (\n: a line break), the scene features it renders (SceneFeature bits), the
# default sampler and --adaptive threshold (empty, 0: none).
SUMMARY  = Step 04: Phong shading with point and directional lights, no shadows.
FEATURES = SCENE_CAMERA | SCENE_LIGHTS
SAMPLER  =
ADAPTIVE = 0

# The default scene, compiled into the program.
SCENE = scenes/spheres.scene
# The unit tests, tests/test_NAME.c, that make test-step 4 runs.
TESTS = light phong

# The reference image images/04-phong.png: the default scene at WIDTH HEIGHT with
# these options (besides --threads 2 --quiet); the Phong terms drawn alone
# (images/04-phong.TERM.png); the image test's tolerance: TOL FRACTION MAX (a
# channel may be off by TOL/255 in at most FRACTION of the channels, never
# by more than MAX/255; tests/image_test.c).
IMAGE_SIZE  = 320 240
IMAGE_ARGS  =
IMAGE_TERMS = ambient diffuse specular
IMAGE_TOL   = 1.5 0.001 16

# The reference traces (make trace-step 4 X Y), a file per pixel in
# tests/traces/04-phong/: TRACE_X_Y = [more options] | what the pixel shows,
# as its trace shows it (X from the left, Y from the top), each rendered with
# TRACE_ARGS.
TRACE_ARGS = --width 320 --height 240
TRACE_171_99 = | the highlight on the red sphere: the specular term
TRACE_140_130 = | the red sphere where both lights are behind the surface: n.l < 0, nothing added
TRACE_250_200 = | the floor lit by both lights: diffuse only
