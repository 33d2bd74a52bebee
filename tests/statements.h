/* The lists an unknown word's message gives, for the tests' expected
 * messages. Generated from the parser's statement table by
 * tools/figures/statements.sh (make regen-statements); do not edit. */
#ifndef RT_TEST_STATEMENTS_H
#define RT_TEST_STATEMENTS_H

#define STATEMENTS \
  "(film, camera, ambient, background, material, plane, sphere, disc, light, samples, light_samples)"
#define LIGHT_TYPES "(point, directional, area)"

#endif
