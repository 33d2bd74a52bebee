build-v3/obj/common/app/cli.o: common/app/cli.c common/app/cli.h \
 common/app/image.h common/film.h common/vec.h common/app/render.h \
 common/scene.h common/camera.h common/ray.h common/light.h common/quad.h \
 common/material.h common/plane.h common/sphere.h common/sampler.h
common/app/cli.h:
common/app/image.h:
common/film.h:
common/vec.h:
common/app/render.h:
common/scene.h:
common/camera.h:
common/ray.h:
common/light.h:
common/quad.h:
common/material.h:
common/plane.h:
common/sphere.h:
common/sampler.h:
