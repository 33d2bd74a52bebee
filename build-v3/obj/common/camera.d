build-v3/obj/common/camera.o: common/camera.c common/camera.h \
 common/ray.h common/vec.h
common/camera.h:
common/ray.h:
common/vec.h:
