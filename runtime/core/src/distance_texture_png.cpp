#include "tidewater/detail/distance_texture_png.hpp"

#include <fmt/format.h>
#include <stb/stb_image.h>

#include <cstdio>
#include <vector>

#include "tidewater/detail/image_io.hpp"

namespace tidewater::detail {

Result<std::shared_ptr<const DistanceTexture>> read_distance_texture_png(const std::filesystem::path& path,
                                                                         std::uint32_t slices, double range) {
    const std::string name = path.string();
    auto refuse = [&](const std::string& what) {
        return Error{ErrorCode::schema_error, fmt::format("{}: {}", name, what)};
    };
    if (slices < DistanceTexture::kMinSide || slices > DistanceTexture::kMaxSide)
        return refuse(fmt::format("{} slices; a distance texture has {} to {}", slices, DistanceTexture::kMinSide,
                                  DistanceTexture::kMaxSide));
    if (!(std::isfinite(range) && range > 0.0 && range <= 1e5))
        return refuse(fmt::format("range {} is out of range (0 < value <= 1e5 m)", range));
    std::FILE* f = std::fopen(name.c_str(), "rb");
    if (!f) return Error{ErrorCode::io_error, fmt::format("{}: cannot open file", name)};
    // The sides before the pixels, so that a huge image is refused unread.
    int w = 0, h = 0, channels = 0;
    if (stbi_info_from_file(f, &w, &h, &channels) &&
        (w < 2 || w > static_cast<int>(DistanceTexture::kMaxSide) || h % static_cast<int>(slices) != 0 ||
         h / static_cast<int>(slices) < 2 ||
         h / static_cast<int>(slices) > static_cast<int>(DistanceTexture::kMaxSide))) {
        std::fclose(f);
        return refuse(fmt::format("{}x{} pixels is not {} slices of 2 to {} samples a side (width x slices * height)",
                                  w, h, slices, DistanceTexture::kMaxSide));
    }
    auto image = read_png_gray16(f, name);  // closes f; names the file in its errors
    if (!image) return image.error();
    const glm::uvec3 size(static_cast<unsigned>(image->width), static_cast<unsigned>(image->height) / slices, slices);
    std::vector<float> distances(std::size_t{size.x} * size.y * size.z);
    for (std::uint32_t k = 0; k < size.z; ++k)
        for (std::uint32_t j = 0; j < size.y; ++j) {
            const std::size_t row = std::size_t{k} * size.y + (size.y - 1 - j);  // a slice's top row: its highest y
            for (std::uint32_t i = 0; i < size.x; ++i)
                distances[i + size.x * (j + std::size_t{size.y} * k)] =
                    static_cast<float>(distance_of_texel(image->pixels[row * size.x + i], range));
        }
    auto texture = DistanceTexture::create(size, std::move(distances));
    if (!texture) return refuse(texture.error().message);
    return texture;
}

}  // namespace tidewater::detail
