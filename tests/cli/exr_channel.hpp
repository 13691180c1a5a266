// One channel of an EXR file the CLI wrote (the depth and field AOVs), read by OpenEXR itself,
// so that tests check the files with a reader that is not the writer's code.
#pragma once
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>

#include <string>
#include <vector>

namespace inkshade::test {

// Channel `name`, top row first, its size in width and height; empty when the file has no
// such channel.
inline std::vector<float> read_exr_channel(const std::string& path, const char* name, int& width, int& height) {
    Imf::InputFile file(path.c_str());
    if (!file.header().channels().findChannel(name)) return {};
    const Imath::Box2i box = file.header().dataWindow();
    width = box.max.x - box.min.x + 1;
    height = box.max.y - box.min.y + 1;
    std::vector<float> v(size_t(width) * size_t(height));
    Imf::FrameBuffer frame;
    frame.insert(
        name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(v.data()), sizeof(float), sizeof(float) * size_t(width)));
    file.setFrameBuffer(frame);
    file.readPixels(box.min.y, box.max.y);
    return v;
}

}  // namespace inkshade::test
