/// @file main.cpp
/// The `impulse2d` program.
#include "app/cli.h"

int main(int argc, char** argv) { return impulse2d::demos::run_cli(argc, argv); }
