build-v3/obj/common/accel/accel.o: common/accel/accel.c \
 common/accel/accel.h common/scene.h common/camera.h common/ray.h \
 common/vec.h common/light.h common/quad.h common/material.h \
 common/plane.h common/sphere.h common/accel/bvh.h common/accel/hull.h \
 common/plane.h common/quad.h
common/accel/accel.h:
common/scene.h:
common/camera.h:
common/ray.h:
common/vec.h:
common/light.h:
common/quad.h:
common/material.h:
common/plane.h:
common/sphere.h:
common/accel/bvh.h:
common/accel/hull.h:
common/plane.h:
common/quad.h:
