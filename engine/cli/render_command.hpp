#pragma once
// `washout render RUN.h5 ...`: draws the frames of a finished (or still running) run as PNG
// images, optionally stitched into a video by ffmpeg when it is installed. See docs/render.md.
namespace washout::cli {

// argv[0] is "render", the rest are its options. Returns the exit status: 0 success,
// 1 bad input (missing or unreadable run file, unknown field or option, frame index out of
// range), 3 output could not be written (folder, image, video).
int run_render_command(int argc, char** argv);

}  // namespace washout::cli
