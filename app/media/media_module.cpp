/// @file
/// @brief The entry point of the media module (libvdfx_media.so): every command, with the video,
/// image and GL libraries they need. app/cli/main.cpp loads it for every command that is not light
/// (app/cli/commands.inc). Takes the arguments after the program name.
#include "app/media/media_commands.h"

extern "C" __attribute__((visibility("default"))) int vdfx_media_main(int argc, char** argv) {
  return vdfx::app::run_main(vdfx::app::Args(argv, argv + argc));
}
