// A HapticState to and from the packed columns of proxima_remote.proto's TickColumns: the fields
// of a trace row, nothing rounded, so that a remote trace equals a local one.
#pragma once

#include "Runtime/HapticState.h"

#include "proxima_remote.pb.h"

#include <functional>

namespace proxima
{

/// Ticks per streamed message: about 400 KB, well under gRPC's default limit.
inline constexpr int kTicksPerMessage = 4096;

void appendTick(const HapticState& state, net::TickColumns& columns);
/// Every tick of `columns`, in order; throws std::runtime_error when its columns disagree in
/// length.
void forEachTick(const net::TickColumns& columns, const std::function<void(const HapticState&)>& f);

} // namespace proxima
