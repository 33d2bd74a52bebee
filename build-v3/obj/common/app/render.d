build-v3/obj/common/app/render.o: common/app/render.c common/app/render.h \
 common/film.h common/vec.h common/scene.h common/camera.h common/ray.h \
 common/light.h common/quad.h common/material.h common/plane.h \
 common/sphere.h
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
