#include <simp/obs/ObjectStyle.h>

#include <mrpt/opengl/CBox.h>
#include <mrpt/opengl/CText.h>
#include <mrpt/poses/CPose3D.h>

#include <cstdlib>

namespace simp::obs {

std::array<std::uint8_t, 3> classColorRgb(int class_id) {
    static constexpr std::array<std::array<std::uint8_t, 3>, 14> kPalette = {{{31, 119, 180},
                                                                             {255, 127, 14},
                                                                             {44, 160, 44},
                                                                             {214, 39, 40},
                                                                             {148, 103, 189},
                                                                             {140, 86, 75},
                                                                             {227, 119, 194},
                                                                             {127, 127, 127},
                                                                             {188, 189, 34},
                                                                             {23, 190, 207},
                                                                             {255, 187, 120},
                                                                             {152, 223, 138},
                                                                             {255, 152, 150},
                                                                             {197, 176, 213}}};
    const auto i = static_cast<std::size_t>(std::labs(static_cast<long>(class_id))) % kPalette.size();
    return kPalette[i];
}

void appendLabelledBox(const geometry::Box3D& b, int class_id, const std::string& label,
                       mrpt::opengl::CSetOfObjects& out) {
    const auto color = classColorRgb(class_id);
    const mrpt::math::TPoint3D half(0.5 * b.size.x(), 0.5 * b.size.y(), 0.5 * b.size.z());
    auto box = mrpt::opengl::CBox::Create(-half, half, /*is_wireframe=*/true, /*lineWidth=*/2.0f);
    mrpt::math::CMatrixDouble33 R;
    R.asEigen() = b.R;
    mrpt::math::CVectorFixedDouble<3> t;
    t[0] = b.center.x();
    t[1] = b.center.y();
    t[2] = b.center.z();
    box->setPose(mrpt::poses::CPose3D(R, t));
    box->setColor_u8(color[0], color[1], color[2]);
    box->setName(label);
    out.insert(box);

    auto text = mrpt::opengl::CText::Create(label);
    text->setLocation(b.center.x(), b.center.y(), b.center.z() + 0.5 * b.size.z() + 0.1);
    text->setColor_u8(color[0], color[1], color[2]);
    out.insert(text);
}

}  // namespace simp::obs
