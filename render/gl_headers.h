#pragma once
// GLEW must precede every GL header; include this instead of any GL header.
#include <GL/glew.h>
