// A HapticState to and from the packed columns of proxima_remote.proto's TickColumns, and a body's
// pose to and from its BodyPoseColumns: the fields of a trace row and of a --bodies-out row,
// nothing rounded, so that a remote run's files equal a local run's.
#pragma once

#include "IO/ScriptedRun/ScriptedRun.h"
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

void appendBodyPose(const BodyPoseRow& row, net::BodyPoseColumns& columns);
/// Every row of `columns`, in order; throws std::runtime_error when its columns disagree in
/// length.
void forEachBodyPose(const net::BodyPoseColumns& columns,
                     const std::function<void(const BodyPoseRow&)>& f);

} // namespace proxima
