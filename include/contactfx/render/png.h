// contactfx_render: images as PNG file bytes, the one PNG encoder of contactfx.
//
// The Cairo renderer's frames, the tuning plot and the testbed's screenshots are all encoded here (by
// Cairo's PNG writer), in memory; files are then written atomically (contactfx/files/text_file.h).
#pragma once

#include <string>

namespace cfx::render
{

/// PNG bytes of a `width` x `height` image (each in [1, 16384]) given as rows, top first, `stride`
/// bytes apart (>= 4 * width, a multiple of 4), of native-endian 32-bit ARGB words with premultiplied
/// alpha: Cairo's ARGB32, CairoRenderer::Rows(). Fully opaque pixels (alpha 0xFF) need no premultiplying.
/// Throws std::invalid_argument for a bad size or stride and std::runtime_error when encoding fails.
std::string EncodePng(const unsigned char* rows, int width, int height, int stride);

/// The largest width or height (pixels) of an image the renderers draw and EncodePng encodes.
inline constexpr int kMaxImageSide = 16384;

} // namespace cfx::render
