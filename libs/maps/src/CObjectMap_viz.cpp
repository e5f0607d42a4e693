#include <mrpt/opengl/CBox.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/opengl/CText.h>
#include <mrpt/poses/CPose3D.h>
#include <simp/maps/CObjectMap.h>

namespace simp::maps {

std::array<std::uint8_t, 3> CObjectMap::classColor(int class_id) {
    // 14 distinct colours, one per class of the paper's detector; repeats beyond.
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
    const std::size_t i = static_cast<std::size_t>(class_id < 0 ? -class_id : class_id) % kPalette.size();
    return kPalette[i];
}

void CObjectMap::getVisualizationInto(mrpt::opengl::CSetOfObjects& outObj) const {
    if (!genericMapParams.enableSaveAs3DObject) return;
    for (const auto& obj : m_data.objects) {
        const auto& b = obj.box;
        const auto color = classColor(obj.class_id);
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
        outObj.insert(box);

        const std::string name = obj.class_id >= 0 && static_cast<std::size_t>(obj.class_id) < m_data.class_names.size()
                                     ? m_data.class_names[static_cast<std::size_t>(obj.class_id)]
                                     : "?";
        auto label = mrpt::opengl::CText::Create(name + " #" + std::to_string(obj.id));
        label->setLocation(b.center.x(), b.center.y(), b.center.z() + 0.5 * b.size.z() + 0.1);
        label->setColor_u8(color[0], color[1], color[2]);
        outObj.insert(label);
    }
}

}  // namespace simp::maps
