#pragma once
// Everything a plugin author needs.
#include <darkroom/buffer.h>
#include <darkroom/camera.h>
#include <darkroom/capture_backend.h>
#include <darkroom/colormap.h>
#include <darkroom/context.h>
#include <darkroom/error.h>
#include <darkroom/filter.h>
#include <darkroom/input_file.h>
#include <darkroom/limits.h>
#include <darkroom/plugin.h>
#include <darkroom/port.h>
#include <darkroom/registrar.h>
#include <darkroom/row.h>
#include <darkroom/scene.h>
#include <darkroom/value.h>
#include <darkroom/version.h>
