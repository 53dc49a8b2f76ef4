// Shading formulas are evaluated per pixel inside the rasterizer's tile loop, which is compiled
// twice (baseline and AVX2, raster/pipeline.h). Compilers do not inline across such targets on
// their own, so the formulas both renderers share are forced inline into each copy.
#pragma once

#if defined(__GNUC__)
#define OBSCURA_SHADING_INLINE [[gnu::always_inline]] inline
#else
#define OBSCURA_SHADING_INLINE inline
#endif
