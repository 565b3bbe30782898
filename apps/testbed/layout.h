// contactfx-testbed: where things are in the window.
//
// The world view fills the window left of one column of panels, so the panels never cover the scene.
// Shared with the screenshot test, which looks at the world view only.
#pragma once

#include <algorithm>

namespace cfx::testbed
{

/// Default window size, px.
inline constexpr int kDefaultWidth = 1280;
inline constexpr int kDefaultHeight = 720;

/// Width of the panel column on the right, px.
inline constexpr int kPanelWidth = 390;

/// A rectangle in window pixels, origin at the top left.
struct PixelRect
{
    int x = 0;
    int y = 0;
    int width = 1;
    int height = 1;
};

/// The part of a `width` x `height` window that shows the world (at least one pixel): all of it when the
/// panels are hidden (Tab).
inline PixelRect WorldViewRect(int width, int height, bool panelsShown = true)
{
    return PixelRect{0, 0, std::max(1, width - (panelsShown ? kPanelWidth : 0)), std::max(1, height)};
}

} // namespace cfx::testbed
