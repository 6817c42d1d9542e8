// The built-in scenes, one line each: IMPULSE2D_SCENE(name) names the function
// `Scene impulse2d::demos::scenes::name()` defined in demos/scenes/name.cpp. The first line is
// the default demo of `impulse2d` run without arguments. No include guard: this file is
// included with different definitions of IMPULSE2D_SCENE (see scene_registry.cpp).
IMPULSE2D_SCENE(tutorial)
IMPULSE2D_SCENE(materials)
IMPULSE2D_SCENE(friction_ramp)
IMPULSE2D_SCENE(push)
IMPULSE2D_SCENE(heavy_on_light)
IMPULSE2D_SCENE(shape_pairs)
IMPULSE2D_SCENE(pyramid)
IMPULSE2D_SCENE(stack)
IMPULSE2D_SCENE(newtons_cradle)
IMPULSE2D_SCENE(bullet)
IMPULSE2D_SCENE(ball_pit)
IMPULSE2D_SCENE(random_polygons)
IMPULSE2D_SCENE(platformer)
