#include <simp/obs/ObjectStyle.h>

#include <mrpt/opengl/CBox.h>
#include <mrpt/opengl/CText.h>
#include <mrpt/poses/CPose3D.h>

namespace simp::obs {

void appendLabelledBox(const geometry::Box3D& b, const Rgb& color, const std::string& label,
                       mrpt::opengl::CSetOfObjects& out) {
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
