#include "methods/probe_params.h"

namespace mirage {

ParamSpec envmapSizeParam() {
  return ParamSpec::integer("envmap-size", 8, 2048, 256,
                            "face size of each reflector's cube map, in texels");
}

ParamSpec probeProxyParam() {
  return ParamSpec::choice<ProbeProxy>(
      "proxy", kProbeProxies, ProbeProxy::kBox,
      "envmap-box's proxy of the room: its box, or the box's circumscribed "
      "sphere (Bjorke)");
}

ParamSpec beyondOrderParam() {
  return ParamSpec::choice<BeyondOrder>(
      "beyond-order", kBeyondOrders, BeyondOrder::kProbe,
      "a reflector met after the method's last bounce (at --order above the method's own): shown "
      "through its reflection probe, or in its base colour");
}

}  // namespace mirage
