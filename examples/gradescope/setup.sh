#!/usr/bin/env bash
# Gradescope runs this once, as root, when it builds the autograder's image: it installs what
# vkrt needs and builds vkrt from the copy of its source in the zip (vkrt/), then puts the
# binary on the PATH. About 5 minutes. (README.md: which base image to choose.)
set -euo pipefail
source_dir="${AUTOGRADER_ROOT:-/autograder}/source"
bash "$source_dir/vkrt/.ci/install-deps"
cmake -S "$source_dir/vkrt" -B "$source_dir/vkrt/build" -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build "$source_dir/vkrt/build" --target vkrt
install -m 755 "$source_dir/vkrt/build/vkrt" /usr/local/bin/vkrt
vkrt --version
