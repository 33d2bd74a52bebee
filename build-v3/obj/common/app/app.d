build-v3/obj/common/app/app.o: common/app/app.c common/app/app.h \
 common/app/render.h common/film.h common/vec.h common/scene.h \
 common/camera.h common/ray.h common/light.h common/quad.h \
 common/material.h common/plane.h common/sphere.h common/accel/accel.h \
 common/app/cli.h common/app/image.h common/app/parser.h common/sampler.h
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
common/accel/accel.h:
common/app/cli.h:
common/app/image.h:
common/app/parser.h:
common/sampler.h:
