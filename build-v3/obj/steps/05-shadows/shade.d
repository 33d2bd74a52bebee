build-v3/obj/steps/05-shadows/shade.o: steps/05-shadows/shade.c \
 steps/05-shadows/shade.h common/app/render.h common/film.h common/vec.h \
 common/scene.h common/camera.h common/ray.h common/light.h common/quad.h \
 common/material.h common/plane.h common/sphere.h
steps/05-shadows/shade.h:
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
