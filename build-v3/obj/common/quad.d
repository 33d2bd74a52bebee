build-v3/obj/common/quad.o: common/quad.c common/quad.h common/ray.h \
 common/vec.h
common/quad.h:
common/ray.h:
common/vec.h:
