// The knobs of a remote run between ScriptedRunSettings and the RunSettings message, driven by
// the settings table (IO/ScriptedRun/RunSettingTable.h): each row's field of the message is the
// one named as its keyword, found by protobuf's reflection, so that client and server copy every
// knob the table has, and a knob added to the table needs no edit here.
#pragma once

#include "IO/ScriptedRun/ScriptedRunSettings.h"

#include "proxima_run_settings.pb.h"

namespace proxima::detail
{

/// Every knob of `settings` into `message` (max_ticks is the caller's).
void writeRunSettings(const ScriptedRunSettings& settings, net::RunSettings& message);
/// Every knob of `message` into `settings`; the files (mesh, scene, path, texture) are the
/// caller's.
void readRunSettings(const net::RunSettings& message, ScriptedRunSettings& settings);

} // namespace proxima::detail
