#pragma once
// Where a setting's default comes from and why, as settings_fields.h states it for the
// settings reference (docs/settings.md). Reading and writing settings ignore it.
#include "core/enum_names.h"

namespace slamkit {

enum class SettingSource {
  kPaper,     // the front end's source paper (docs/method.md#sources)
  kOrbSlam2,  // ORB-SLAM2's value, where the paper gives none
  kSlamkit,   // slamkit's own choice
};
inline constexpr EnumNames<SettingSource, 3> kSettingSourceNames = {
    {{SettingSource::kPaper, "paper"},
     {SettingSource::kOrbSlam2, "ORB-SLAM2"},
     {SettingSource::kSlamkit, "slamkit"}}};

struct SettingNote {
  SettingSource source;
  const char* why;  // one short line
};
constexpr SettingNote from_paper(const char* why) { return {SettingSource::kPaper, why}; }
constexpr SettingNote from_orb_slam2(const char* why) { return {SettingSource::kOrbSlam2, why}; }
constexpr SettingNote from_slamkit(const char* why) { return {SettingSource::kSlamkit, why}; }

}  // namespace slamkit
