// The calls an input makes: `one_call` decodes the next call from the input and makes it through
// `checked`; the groups below are the calls that check more than the general rules (round trips,
// the gu texture manager, files) or that take several steps.
#pragma once

#include <fuzzer/FuzzedDataProvider.h>
#include <glide.h>

#include <string>
#include <vector>

namespace glide_api_fuzz {

extern std::string g_scratch;  // a directory of the build tree for the files calls read and write
extern GrState g_saved_state;  // grGlideGetState's block from earlier in this input
extern bool g_have_saved_state;

// One call decoded from the input; `span` is the screen's larger side (pixels), for arguments
// near its edges.
void one_call(FuzzedDataProvider &in, float span);
void more_calls(FuzzedDataProvider &in, float span);

// round_trips.cpp
void lfb_round_trip(FuzzedDataProvider &in);
void texture_memory_round_trip(FuzzedDataProvider &in);
void state_round_trip();
void polygon(FuzzedDataProvider &in, float span);

// utility_calls.cpp
void three_df(FuzzedDataProvider &in);
std::vector<FxU8> rle_bitmap(FuzzedDataProvider &in, long rows);
GrMipMapId_t mip_map_id(FuzzedDataProvider &in);
void gu_allocate(FuzzedDataProvider &in);
void gu_change(FuzzedDataProvider &in);
void gu_download(FuzzedDataProvider &in);
void lfb_layout(FuzzedDataProvider &in);
void getters();
void multipass(FuzzedDataProvider &in, float span);
void close_and_reopen(FuzzedDataProvider &in);
void textured_draw(FuzzedDataProvider &in, float span);

}  // namespace glide_api_fuzz
