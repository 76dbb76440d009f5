// Deterministic train/val/test assignment by source subject, so that no performer appears in two splits, with
// HumanML3D's 80/5/15 proportions counted in clips within each source (the key's text before its first '/':
// "CMU/07" -> CMU), so that every source, and with it every activity only one source holds (ReActIdle's
// standing), is in the training split. Within a source the keys are ordered by a stable 64-bit hash of their
// text (FNV-1a, then mixed; not std::hash, which differs between platforms) and dealt out in that order: a key
// goes to train while the source's clips dealt before it are under 0.80 of its clips, then to val under 0.85,
// then to test.
#pragma once
#include <cstdint>
#include <map>
#include <string>

namespace t2imu {

enum class Split { train, val, test };

std::map<std::string, Split> assign_splits(const std::map<std::string, int>& clips_per_key);
const char* split_name(Split s);

}  // namespace t2imu
