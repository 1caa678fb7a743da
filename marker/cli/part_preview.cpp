#include "marker/cli/part_preview.hpp"

#include "marker/preview/mark_preview.hpp"
#include "marker/production/part_picture.hpp"

namespace mark::cli {

std::string next_part_preview(const JobFile& job, const JobFonts& fonts, const std::vector<ObjectText>& texts,
                              const std::string& format) {
  const PartPicture picture = simulate_part(job, fonts, texts);
  return encode_mark_preview(picture.plan(), picture.dose(), format);
}

}  // namespace mark::cli
