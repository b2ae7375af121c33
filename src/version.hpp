// "clrt X.Y.Z (commit HASH)": what --version, --stats and the experiment records print.
#pragma once

const char* clrt_version_string();
