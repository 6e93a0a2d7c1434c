#include "input/action.h"

#include <stddef.h>

const char *const app_action_names[ACTION_COUNT + 1] = {
    "none",	      "turn-left",    "turn-right",    "turn-up",	"turn-down",
    "next-matcap",    "prev-matcap",  "toggle-camera", "next-mode",	"reset",
    "next-model",     "prev-model",   "next-stop",     "prev-stop",	"play-pause",
    "next-animation", "next-variant", "select",	       "next-language", NULL};

const char *const input_kind_names[INPUT_KINDS] = {"other", "button", "key", "touch", "knob"};
