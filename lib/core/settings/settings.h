#pragma once
// Every setting of a run, one struct per module. Each default is tagged with its source:
// (paper), (ORB-SLAM2) or (slamkit) (docs/method.md#sources). A run writes the settings it used
// (settings.yaml) so that any result can be reproduced.
#include "core/settings/fusion_settings.h"
#include "core/settings/keyframe_settings.h"
#include "core/settings/loop_settings.h"
#include "core/settings/mapping_settings.h"
#include "core/settings/matcher_settings.h"
#include "core/settings/optimization_settings.h"
#include "core/settings/orb_settings.h"
#include "core/settings/pipeline_settings.h"
#include "core/settings/report_settings.h"
#include "core/settings/tracking_settings.h"
#include "core/settings/vocabulary_settings.h"

namespace slamkit {

struct Settings {
  OrbSettings orb;
  MatcherSettings matcher;
  TrackingSettings tracking;
  KeyframeSettings keyframes;
  MappingSettings mapping;
  OptimizationSettings optimization;
  LoopSettings loop;
  FusionSettings map;
  VocabularySettings vocabulary;
  PipelineSettings pipeline;
  ReportSettings report;
};

}  // namespace slamkit
