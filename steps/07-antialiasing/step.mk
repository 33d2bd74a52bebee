# Step 07's manifest: what the build, the image test, the traces, the
# report and the grader know of the step (docs/instructors.md, "A step's
# manifest"). KEY = value, one line each; `make regen` after a change.

# The Step fields of main.c (build/gen/07-antialiasing/step_manifest.h): the --help line
# (\n: a line break), the scene features it renders (SceneFeature bits), the
# default sampler and --adaptive threshold (empty, 0: none).
SUMMARY  = Step 07: antialiasing, several samples per pixel and adaptive sampling.\nDefaults: the scene's samples, --adaptive 0.05 (corners and centre, cut in\nfour where they differ); with --adaptive 0, --sampler sobol (unbiased).
FEATURES = SCENE_CAMERA | SCENE_LIGHTS | SCENE_SHADOWS | SCENE_AMBIENT | SCENE_LIGHT_SHAPES | SCENE_SAMPLES
SAMPLER  = sobol
ADAPTIVE = 0.05

# The default scene, compiled into the program.
SCENE = scenes/antialiasing.scene
# The unit tests, tests/test_NAME.c, that make test-step 7 runs.
TESTS = sampler antialiasing

# The reference image images/07-antialiasing.png: the default scene at WIDTH HEIGHT with
# these options (besides --threads 2 --quiet); the Phong terms drawn alone
# (images/07-antialiasing.TERM.png); the image test's tolerance: TOL FRACTION MAX (a
# channel may be off by TOL/255 in at most FRACTION of the channels, never
# by more than MAX/255; tests/image_test.c).
IMAGE_SIZE  = 320 240
IMAGE_ARGS  =
IMAGE_TERMS = ambient diffuse specular
IMAGE_TOL   = 1.5 0.001 16

# The reference traces (make trace-step 7 X Y), a file per pixel in
# tests/traces/07-antialiasing/: TRACE_X_Y = [more options] | what the pixel shows,
# as its trace shows it (X from the left, Y from the top), each rendered with
# TRACE_ARGS.
TRACE_ARGS = --width 320 --height 240
TRACE_125_100 = | the red sphere's left silhouette over the floor: corners and centre disagree, the pixel is cut in four and the quarters the edge crosses again, down to the leaves (35 samples)
TRACE_250_200 = | the floor: corners and centre agree, the pixel is not cut (5 samples)
