// wavepath-contact-sheet: lays PNG frames of an image sequence out in a grid, for the docs.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <stb_image.h>
#include <stb_image_write.h>

int main(int argc, char** argv) {
  CLI::App app{"wavepath-contact-sheet: the frames in a grid, left to right, then top to bottom"};
  std::string output;
  std::vector<std::string> frames;
  int columns = 4;
  int gap = 4;
  app.add_option("-o,--output", output, "Output PNG")->required();
  app.add_option("--columns", columns, "Frames per row")->check(CLI::Range(1, 64));
  app.add_option("--gap", gap, "Black pixels between frames")->check(CLI::Range(0, 256));
  app.add_option("frames", frames, "Frames (PNG), all of one size")->required();
  CLI11_PARSE(app, argc, argv);

  int width = 0;
  int height = 0;
  std::vector<unsigned char> sheet;
  int sheetWidth = 0;
  for (size_t i = 0; i < frames.size(); ++i) {
    int w = 0, h = 0, channels = 0;
    unsigned char* pixels = stbi_load(frames[i].c_str(), &w, &h, &channels, 3);
    if (!pixels || (i > 0 && (w != width || h != height))) {
      std::fprintf(stderr, "wavepath-contact-sheet: error: %s: %s; give PNG frames of one size\n", frames[i].c_str(),
                   pixels ? "its size differs from the first frame's" : stbi_failure_reason());
      stbi_image_free(pixels);
      return 1;
    }
    if (i == 0) {
      width = w;
      height = h;
      const int cols = std::min<int>(columns, int(frames.size()));
      const int rows = int((frames.size() + size_t(columns) - 1) / size_t(columns));
      sheetWidth = cols * width + (cols - 1) * gap;
      sheet.assign(size_t(sheetWidth) * size_t(rows * height + (rows - 1) * gap) * 3, 0);
    }
    const int x0 = int(i % size_t(columns)) * (width + gap);
    const int y0 = int(i / size_t(columns)) * (height + gap);
    for (int y = 0; y < height; ++y) {
      std::copy_n(pixels + size_t(y) * size_t(width) * 3, size_t(width) * 3,
                  sheet.begin() + (size_t(y0 + y) * size_t(sheetWidth) + size_t(x0)) * 3);
    }
    stbi_image_free(pixels);
  }
  const int sheetHeight = int(sheet.size() / 3 / size_t(sheetWidth));
  if (!stbi_write_png(output.c_str(), sheetWidth, sheetHeight, 3, sheet.data(), sheetWidth * 3)) {
    std::fprintf(stderr, "wavepath-contact-sheet: error: cannot write %s; check the directory exists\n",
                 output.c_str());
    return 1;
  }
  return 0;
}
