#pragma once
/// @file viewer_golden.h
/// The browser viewer's golden (test_cli_html.cpp), named here so that the golden inventory
/// (test_golden_inventory.cpp) counts it as used.

namespace impulse2d::testing {

/// golden_images/<this>.png and .json: the tutorial's `render --html` page in headless
/// Chromium at frame 3 with the normals overlay variant.
inline constexpr const char* kViewerGolden = "viewer/tutorial_frame3_normals";

}  // namespace impulse2d::testing
