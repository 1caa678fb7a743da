// Every command that reads an image file goes through the one reader: the PNG that declares
// 20000 x 20000 pixels and a truncated PNG get the same one-line refusal, naming the file, from
// `gravure IMAGE`, `gravure --mask`, `gcode --tool-image` and `tool-measure`, and nothing is
// written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "png_writer.hpp"
#include "tests/marker/cli_runner.hpp"

namespace fs = std::filesystem;

namespace mark::test {
namespace {

std::vector<std::vector<std::string>> every_reader(const std::string& image, const std::string& good,
                                                   const std::string& out) {
  // A preview's name must end in .png or .svg (checked before the image is read).
  const std::string preview = out + ".png";
  return {{"gravure", image, "--preview", preview},
          {"gravure", good, "--mask", image, "--preview", preview},
          {"gcode", "A", "--mode", "protrusion", "--tool-image", image, "--pixel-size", "5", "-o", out},
          {"tool-measure", image, "--pixel-size", "5"}};
}

TEST(ImageCallers, EveryCommandRefusesHostilePngsWithTheSameLine) {
  const fs::path dir = fresh_temp_dir("marker_image_callers");
  const auto put = [&](const std::string& name, const std::string& bytes) {
    std::ofstream(dir / name, std::ios::binary) << bytes;
    return (dir / name).string();
  };
  PngSpec spec;
  spec.width = 40, spec.height = 30;
  spec.pixel = [](int x, int y) { return std::vector<unsigned>{static_cast<unsigned>((x + y) % 2 * 255)}; };
  const std::string png = write_png(spec);
  const std::string good = put("good.png", png);
  const std::string bomb = put("bomb.png", png_header_only(20000, 20000));
  const std::string cut = put("cut.png", png.substr(0, png.size() / 2));
  const std::string out = (dir / "never.out").string();
  for (const auto& [image, line] :
       {std::pair{bomb, "marker: '" + bomb + "': PNG of 20000x20000 pixels is larger than 100000000 pixels\n"},
        std::pair{cut, "marker: '" + cut + "': truncated PNG data (libpng: the file ends inside a chunk)\n"}})
    for (const std::vector<std::string>& args : every_reader(image, good, out)) {
      const CliResult r = run_cli(args);
      EXPECT_EQ(r.code, 1) << args[0] << " " << args[1];
      EXPECT_EQ(r.err, line) << args[0] << " " << args[1];
      EXPECT_FALSE(fs::exists(out));
      EXPECT_FALSE(fs::exists(out + ".png"));
    }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace mark::test
