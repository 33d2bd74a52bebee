build-v3/obj/common/app/image.o: common/app/image.c common/app/image.h \
 common/film.h common/vec.h /usr/include/libpng16/png.h \
 /usr/include/libpng16/pnglibconf.h /usr/include/libpng16/pngconf.h \
 /usr/include/stb/stb_image.h /usr/include/stb/stb_image_write.h
common/app/image.h:
common/film.h:
common/vec.h:
/usr/include/libpng16/png.h:
/usr/include/libpng16/pnglibconf.h:
/usr/include/libpng16/pngconf.h:
/usr/include/stb/stb_image.h:
/usr/include/stb/stb_image_write.h:
