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

// What a method shows of a reflector its reflected rays meet after their last bounce (a mirror
// seen in a mirror by an order-1 method, at --order 2 or more): the reflection its probe shows
// there, as engines do, or its base colour (the frames before the probes were asked).
enum class BeyondOrder { kProbe, kBase };
inline constexpr Choice<BeyondOrder> kBeyondOrders[] = {{"probe", BeyondOrder::kProbe},
                                                        {"base", BeyondOrder::kBase}};
// --beyond-order.
ParamSpec beyondOrderParam();

// --envmap-size: the face size of each reflector's cube map, in texels.
ParamSpec envmapSizeParam();
// --proxy: envmap-box's proxy of the room (its box, or the box's circumscribed sphere).
ParamSpec probeProxyParam();

}  // namespace mirage
