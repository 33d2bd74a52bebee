# Step 08's manifest: what the build, the image test, the traces, the
# report and the grader know of the step (docs/instructors.md, "A step's
# manifest"). KEY = value, one line each; `make regen` after a change.

# The Step fields of main.c (build/gen/08-area-lights/step_manifest.h): the --help line
# (\n: a line break), the scene features it renders (SceneFeature bits), the
# default sampler and --adaptive threshold (empty, 0: none).
SUMMARY  = Step 08: area lights, soft shadows from stratified light samples.\nDefaults: the scene's samples and light_samples, --sampler sobol, --adaptive 0\n(unbiased: every pixel takes all its samples).
FEATURES = SCENE_CAMERA | SCENE_LIGHTS | SCENE_SHADOWS | SCENE_AMBIENT | SCENE_LIGHT_SHAPES | SCENE_SAMPLES | SCENE_AREA_LIGHTS
SAMPLER  = sobol
ADAPTIVE = 0

# The default scene, compiled into the program.
SCENE = scenes/area-lights.scene
# The unit tests, tests/test_NAME.c, that make test-step 8 runs.
TESTS = area_light

# The reference image images/08-area-lights.png: the default scene at WIDTH HEIGHT with
# these options (besides --threads 2 --quiet); the Phong terms drawn alone
# (images/08-area-lights.TERM.png); the image test's tolerance: TOL FRACTION MAX (a
# channel may be off by TOL/255 in at most FRACTION of the channels, never
# by more than MAX/255; tests/image_test.c).
IMAGE_SIZE  = 320 240
IMAGE_ARGS  = --samples 16 --light-samples 256 --adaptive 0.05
IMAGE_TERMS = ambient diffuse specular
IMAGE_TOL   = 2 0.001 16

# The reference traces (make trace-step 8 X Y), a file per pixel in
# tests/traces/08-area-lights/: TRACE_X_Y = [more options] | what the pixel shows,
# as its trace shows it (X from the left, Y from the top), each rendered with
# TRACE_ARGS.
TRACE_ARGS = --width 320 --height 240
TRACE_160_20 = | the area light's front face: L = P / A
TRACE_96_160 = | the floor in the red sphere's soft shadow (about 1/7 of the area light hidden) and the gold sphere's shadow from the directional light
TRACE_60_140 = | the green sphere's shadow on the floor: the whole area light hidden, and the directional light
