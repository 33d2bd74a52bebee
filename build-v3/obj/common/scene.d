build-v3/obj/common/scene.o: common/scene.c common/scene.h \
 common/camera.h common/ray.h common/vec.h common/light.h common/quad.h \
 common/material.h common/plane.h common/sphere.h
common/scene.h:
common/camera.h:
common/ray.h:
common/vec.h:
common/light.h:
common/quad.h:
common/material.h:
common/plane.h:
common/sphere.h:
