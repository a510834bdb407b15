// The parameters of the reflection probes (cube maps captured around a reflector) that several
// methods make: envmap and envmap-box, the impostors' captured environment, hybrid's background,
// ssr's fallback. One spec each, so that a parameter of one name has one range, default and help
// whichever method lists it (allMethodParams refuses specs of one name that differ).
#pragma once

#include "methods/params.h"

namespace mirage {

// envmap-box's proxy of the room.
enum class ProbeProxy { kBox, kSphere };
inline constexpr Choice<ProbeProxy> kProbeProxies[] = {{"box", ProbeProxy::kBox},
                                                       {"sphere", ProbeProxy::kSphere}};

// --envmap-size: the face size of each reflector's cube map, in texels.
ParamSpec envmapSizeParam();
// --proxy: envmap-box's proxy of the room (its box, or the box's circumscribed sphere).
ParamSpec probeProxyParam();

}  // namespace mirage
