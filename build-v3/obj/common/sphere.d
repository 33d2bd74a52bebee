build-v3/obj/common/sphere.o: common/sphere.c common/sphere.h \
 common/ray.h common/vec.h
common/sphere.h:
common/ray.h:
common/vec.h:
