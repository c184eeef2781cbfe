#pragma once
// Analytic shapes as Embree user geometry (RTC_GEOMETRY_TYPE_USER): one user primitive per part
// of the shape (engine/scene/analytic_shape.h), with bounds, intersect and occluded callbacks
// that call intersectAnalyticPart, the same function liftToAnalytic uses for G-buffer texels.
#include <embree3/rtcore.h>

#include "engine/rt/rt_scene.h"

namespace diptych {

// A committed-ready user geometry for data.analytic (non-null); `data` is its user data and
// must outlive the scene.
RTCGeometry newAnalyticGeometry(RTCDevice device, RtScene::GeometryData& data);

}  // namespace diptych
