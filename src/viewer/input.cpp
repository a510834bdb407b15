#include "viewer/input.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <fmt/format.h>

#include "core/atomic_file.h"
#include "scene/scene_json_field.h"

namespace mirage {

namespace {

using scene_json::Field;
using scene_json::Json;
using scene_json::Range;

constexpr const char* kButtons[] = {"left", "right", "middle"};

struct NamedKey {
  const char* name;
  int code;
};
constexpr NamedKey kNamedKeys[] = {
    {"SPACE", GLFW_KEY_SPACE},
    {"ESCAPE", GLFW_KEY_ESCAPE},
    {"ENTER", GLFW_KEY_ENTER},
    {"TAB", GLFW_KEY_TAB},
    {"LEFT_SHIFT", GLFW_KEY_LEFT_SHIFT},
    {"RIGHT_SHIFT", GLFW_KEY_RIGHT_SHIFT},
    {"LEFT_CONTROL", GLFW_KEY_LEFT_CONTROL},
};

}  // namespace

int keyCode(const std::string& name) {
  if (name.size() == 1 && name[0] >= 'A' && name[0] <= 'Z') return GLFW_KEY_A + (name[0] - 'A');
  if (name.size() == 1 && name[0] >= '0' && name[0] <= '9') return GLFW_KEY_0 + (name[0] - '0');
  if (name.size() >= 2 && name[0] == 'F') {
    const std::string digits = name.substr(1);
    if (digits.find_first_not_of("0123456789") == std::string::npos && digits.size() <= 2) {
      const int n = std::stoi(digits);
      if (n >= 1 && n <= 12) return GLFW_KEY_F1 + n - 1;
    }
  }
  for (const NamedKey& k : kNamedKeys)
    if (name == k.name) return k.code;
  return -1;
}

std::string keyName(int code) {
  if (code >= GLFW_KEY_A && code <= GLFW_KEY_Z)
    return std::string(1, char('A' + code - GLFW_KEY_A));
  if (code >= GLFW_KEY_0 && code <= GLFW_KEY_9)
    return std::string(1, char('0' + code - GLFW_KEY_0));
  if (code >= GLFW_KEY_F1 && code <= GLFW_KEY_F12)
    return fmt::format("F{}", code - GLFW_KEY_F1 + 1);
  for (const NamedKey& k : kNamedKeys)
    if (code == k.code) return k.name;
  return "";
}

std::vector<ScriptedEvent> parseEventScript(const std::string& file, const std::string& text) {
  const Json doc = scene_json::parseDocument(file, text);
  const Field root(file, doc, "");
  root.allowKeys({"events"}, "an event script");
  std::vector<ScriptedEvent> out;
  for (const Field& f : root.required("events").items()) {
    ScriptedEvent e;
    Field frame = f.required("frame");
    e.frame = frame.integer(0, 100000000);
    if (!out.empty() && e.frame < out.back().frame)
      frame.fail("= {} is before the previous event's frame ({}); events go in frame order",
                 e.frame, out.back().frame);
    Field type = f.required("type");
    const std::string kind = type.string();
    if (kind == "key") {
      f.allowKeys({"frame", "type", "key", "down"}, "a key event");
      Field key = f.required("key");
      e.event.type = InputEvent::Type::kKey;
      e.event.code = keyCode(key.string());
      if (e.event.code < 0)
        key.fail(
            "= {} is not a key name (A..Z, 0..9, F1..F12, SPACE, ESCAPE, ENTER, TAB, "
            "LEFT_SHIFT, RIGHT_SHIFT, LEFT_CONTROL)",
            scene_json::shortQuote(key.string()));
      e.event.down = f.required("down").boolean();
    } else if (kind == "button") {
      f.allowKeys({"frame", "type", "button", "down"}, "a button event");
      Field button = f.required("button");
      const std::string name = button.string();
      e.event.type = InputEvent::Type::kButton;
      e.event.code = -1;
      for (int b = 0; b < 3; ++b)
        if (name == kButtons[b]) e.event.code = b;
      if (e.event.code < 0)
        button.fail("= {} is not a button (left, right, middle)", scene_json::shortQuote(name));
      e.event.down = f.required("down").boolean();
    } else if (kind == "move") {
      f.allowKeys({"frame", "type", "x", "y"}, "a move event");
      e.event.type = InputEvent::Type::kMove;
      e.event.position = {f.required("x").number(Range::closed(-1e5, 1e5)),
                          f.required("y").number(Range::closed(-1e5, 1e5))};
    } else if (kind == "scroll") {
      f.allowKeys({"frame", "type", "x", "y"}, "a scroll event");
      e.event.type = InputEvent::Type::kScroll;
      e.event.position = {f.numberOr("x", 0.0f, Range::closed(-1e3, 1e3)),
                          f.numberOr("y", 0.0f, Range::closed(-1e3, 1e3))};
    } else if (kind == "resize") {
      f.allowKeys({"frame", "type", "width", "height"}, "a resize event");
      e.event.type = InputEvent::Type::kResize;
      e.event.position = {float(f.required("width").integer(16, 16384)),
                          float(f.required("height").integer(16, 16384))};
    } else {
      type.fail("= {} is not an event type (key, button, move, scroll, resize)",
                scene_json::shortQuote(kind));
    }
    out.push_back(e);
  }
  return out;
}

std::vector<ScriptedEvent> loadEventScript(const std::string& path) {
  return parseEventScript(path, readFile(path));
}

std::string eventScriptText(const std::vector<ScriptedEvent>& events) {
  Json list = Json::array();
  for (const ScriptedEvent& s : events) {
    const InputEvent& e = s.event;
    Json j = {{"frame", s.frame}};
    switch (e.type) {
      case InputEvent::Type::kKey:
        j["type"] = "key";
        j["key"] = keyName(e.code);
        j["down"] = e.down;
        break;
      case InputEvent::Type::kButton:
        j["type"] = "button";
        j["button"] = kButtons[std::clamp(e.code, 0, 2)];
        j["down"] = e.down;
        break;
      case InputEvent::Type::kResize:
        j["type"] = "resize";
        j["width"] = int(e.position.x);
        j["height"] = int(e.position.y);
        break;
      case InputEvent::Type::kMove:
      case InputEvent::Type::kScroll:
        j["type"] = e.type == InputEvent::Type::kMove ? "move" : "scroll";
        j["x"] = e.position.x;
        j["y"] = e.position.y;
        break;
    }
    list.push_back(std::move(j));
  }
  return Json{{"events", list}}.dump(1) + "\n";
}

}  // namespace mirage
