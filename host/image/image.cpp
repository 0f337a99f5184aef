// Image helpers that need no I/O (kept as a unit so image.h stays header-light).
#include "image/image.h"
