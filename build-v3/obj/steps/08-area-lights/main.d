build-v3/obj/steps/08-area-lights/main.o: steps/08-area-lights/main.c \
 common/app/app.h common/app/render.h common/film.h common/vec.h \
 common/scene.h common/camera.h common/ray.h common/light.h common/quad.h \
 common/material.h common/plane.h common/sphere.h common/sampler.h \
 steps/08-area-lights/shade.h
common/app/app.h:
common/app/render.h:
common/film.h:
common/vec.h:
common/scene.h:
common/camera.h:
common/ray.h:
common/light.h:
common/quad.h:
common/material.h:
common/plane.h:
common/sphere.h:
common/sampler.h:
steps/08-area-lights/shade.h:
