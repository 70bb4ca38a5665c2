// Loads the media module (media_api.h) on first use, once per process.
#pragma once

#include "io/media_api.h"
#include "visioncore/basics/result.h"

namespace fieldsight::io {

/// The module's functions, or why it could not be loaded (where it was looked for).
Result<const MediaApi*> mediaApi();

} // namespace fieldsight::io
