build-v3/obj/common/plane.o: common/plane.c common/plane.h common/ray.h \
 common/vec.h
common/plane.h:
common/ray.h:
common/vec.h:
