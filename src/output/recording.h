// Recorded runs (docs/recording.md): the static scene once, then one fixed-size frame of
// quantised robot and movable-obstacle state every N ticks. The format (encoding, scene
// header, frames decoded on demand) is recording_format.h; the writer, which streams frames
// to a temporary file during the run and renames it when the run ends, recording_writer.h;
// the readers (the whole file in memory, or one frame at a time), recording_reader.h.
#pragma once
#include "output/recording_format.h"
#include "output/recording_reader.h"
#include "output/recording_writer.h"
