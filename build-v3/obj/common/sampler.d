build-v3/obj/common/sampler.o: common/sampler.c common/sampler.h \
 common/vec.h common/rng.h
common/sampler.h:
common/vec.h:
common/rng.h:
