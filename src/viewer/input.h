// The viewer's input as events — keys, mouse buttons, cursor motion, the wheel — whether they
// come from the window (GLFW callbacks) or from an event script replayed frame by frame
// (`mirage view --events FILE`), so that a script drives the viewer exactly as a user does.
// Scripts are JSON:
//   {"events": [{"frame": 3, "type": "move", "x": 200, "y": 150},
//               {"frame": 3, "type": "button", "button": "left", "down": true},
//               {"frame": 5, "type": "key", "key": "W", "down": true},
//               {"frame": 9, "type": "scroll", "y": 2},
//               {"frame": 12, "type": "resize", "width": 640, "height": 400}]}
// (a resize asks the window for that size, as a user dragging its border) with positions in
// window units from the top-left corner, keys by name (A..Z, 0..9, F1..F12,
// SPACE, ESCAPE, ENTER, TAB, LEFT_SHIFT, RIGHT_SHIFT, LEFT_CONTROL) and frames counted from 0.
#pragma once

#include <string>
#include <vector>

#include "core/math.h"

namespace mirage {

struct InputEvent {
  enum class Type { kKey, kButton, kMove, kScroll, kResize };
  Type type = Type::kMove;
  int code = 0;         // kKey: a GLFW key code; kButton: 0 left, 1 right, 2 middle
  bool down = false;    // kKey, kButton: pressed (true) or released
  vec2 position{0.0f};  // kMove: the cursor; kScroll: the wheel's offsets; kResize: the size
};

struct ScriptedEvent {
  int frame = 0;
  InputEvent event;
};

// Reads an event script; throws InputError naming the file and the field.
std::vector<ScriptedEvent> loadEventScript(const std::string& path);
std::vector<ScriptedEvent> parseEventScript(const std::string& file, const std::string& text);
// The script's text for `events` (what --record-events writes).
std::string eventScriptText(const std::vector<ScriptedEvent>& events);

// The GLFW key code of a key name, or -1; and the name of a code ("" when it has none).
int keyCode(const std::string& name);
std::string keyName(int code);

}  // namespace mirage
