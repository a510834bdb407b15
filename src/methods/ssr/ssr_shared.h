// Method `ssr`: the bindings its passes share with C++, and the per-frame counts it reports.
#ifndef MIRAGE_METHODS_SSR_SSR_SHARED_H
#define MIRAGE_METHODS_SSR_SSR_SHARED_H

// Texture units after MIRAGE_UNIT_METHOD (4), which the fallback method's probes hold.
#define MIRAGE_UNIT_SSR_HIZ 5     // rg32f, mip levels: the hierarchical-Z pyramid, every level
#define MIRAGE_UNIT_SSR_COLOR 6   // rgba16f: the direct view's colour (reflectors at base colour)
#define MIRAGE_UNIT_SSR_DEPTH 8   // the frame's depth: the pyramid build's input
#define MIRAGE_BIND_SSR_COUNTS 5  // uint[MIRAGE_SSR_COUNTS]: the last frame's counts (below)
#define MIRAGE_IMAGE_SSR_LEVEL_IN 0
#define MIRAGE_IMAGE_SSR_LEVEL_OUT 1
#define MIRAGE_SSR_GROUP 8  // the pyramid build's work groups are 8x8

// What became of each reflector pixel's ray, one counter each (their sum is the pixels shaded),
// and the fallback's share of the faded ones.
#define MIRAGE_SSR_HITS 0          // hit the screen's data, at full weight
#define MIRAGE_SSR_FADED 1         // hit, but inside the edge fade (blended with the fallback)
#define MIRAGE_SSR_OFF_SCREEN 2    // left the screen before hitting anything
#define MIRAGE_SSR_NO_HIT 3        // ended (near or far plane) with nothing hit on screen
#define MIRAGE_SSR_BACK_FACE 4     // hit a surface from behind (its front is all we have)
#define MIRAGE_SSR_OUT_OF_STEPS 5  // ran out of --ssr-steps
#define MIRAGE_SSR_OUTCOMES 6
#define MIRAGE_SSR_FADED_WEIGHT 6  // sum over the faded pixels of the fallback's weight, x 1024
#define MIRAGE_SSR_STEPS 7         // sum over the pixels of the pyramid cells their march visited
#define MIRAGE_SSR_COUNTS 8

#endif  // MIRAGE_METHODS_SSR_SSR_SHARED_H
