// The kinematic horizon from an original sensor stream (sensor.strm, design note §4.2).
#pragma once

#include "visioncore/basics/geometry.h"
#include "visioncore/basics/result.h"

#include <optional>
#include <string>
#include <vector>

namespace fieldsight::io {

/// The sensor stream recorded with image stream `image_strm`: "N_sensor.strm" for
/// "N_image.strm", else "sensor.strm" in the same folder; nullopt when there is none.
std::optional<std::string> findSensorStrmFor(const std::string& image_strm);

/// The "Horizon" sensor of each record, A*x + B*y = C in image px, as a Horizon for images
/// `width` px wide. Record k pairs with image frame k; at most `frames` entries. A record whose
/// horizon is invalid or vertical gives nullopt.
Result<std::vector<std::optional<Horizon>>> readSensorHorizons(const std::string& path, int width,
                                                               std::size_t frames);

} // namespace fieldsight::io
