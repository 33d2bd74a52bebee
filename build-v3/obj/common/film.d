build-v3/obj/common/film.o: common/film.c common/film.h common/vec.h
common/film.h:
common/vec.h:
