#include "motion/skeleton_map.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "motion/skeleton.hpp"

namespace t2imu {

namespace {

JointSource at(const std::string& joint) { return {joint, "", 0}; }
JointSource between(const std::string& a, const std::string& b, double t) { return {a, b, t}; }

// Joint centres are placed where SMPL has them: hips at the femur heads, knees, ankles, the foot joint at the toe
// base (the End Site of the foot where the source has no toe joint), wrists at the start of the hand.
// Where the source spine has fewer joints than SMPL's three, the missing ones sit on the source segment at the
// fraction that gives SMPL's proportions (pelvis->spine1->spine2->spine3 = 0.13 : 0.14 : 0.06 m of 0.33 m).
std::vector<SkeletonMap> make_maps() {
    std::vector<SkeletonMap> maps;
    // CMU, cgspeed "Daz-friendly" BVH (hip, abdomen, chest, neck, head; lThigh/lShin/lFoot; lShldr/lForeArm/lHand).
    // Lengths in centimetres (hip about 85 above the floor).
    maps.push_back({"cgspeed_daz",
                    0.01,
                    PositionChannels::replace_offset,
                    true,
                    {{at("hip"),    at("lThigh"),  at("rThigh"),    between("hip", "abdomen", 0.5),
                      at("lShin"),  at("rShin"),   at("abdomen"),   at("lFoot"),
                      at("rFoot"),  at("chest"),   at("lFoot/end"), at("rFoot/end"),
                      at("neck"),   at("lCollar"), at("rCollar"),   at("head"),
                      at("lShldr"), at("rShldr"),  at("lForeArm"),  at("rForeArm"),
                      at("lHand"),  at("rHand")}}});
    // CMU retargeted onto Reallusion's Character Creator rig (CC_Base_*; twist and share bones are ignored).
    maps.push_back(
        {"iclone_cc_base",
         0.01,
         PositionChannels::add_to_offset,
         false,
         {{at("CC_Base_Hip"),         at("CC_Base_L_Thigh"),    at("CC_Base_R_Thigh"),    at("CC_Base_Waist"),
           at("CC_Base_L_Calf"),      at("CC_Base_R_Calf"),     at("CC_Base_Spine01"),    at("CC_Base_L_Foot"),
           at("CC_Base_R_Foot"),      at("CC_Base_Spine02"),    at("CC_Base_L_ToeBase"),  at("CC_Base_R_ToeBase"),
           at("CC_Base_NeckTwist01"), at("CC_Base_L_Clavicle"), at("CC_Base_R_Clavicle"), at("CC_Base_Head"),
           at("CC_Base_L_Upperarm"),  at("CC_Base_R_Upperarm"), at("CC_Base_L_Forearm"),  at("CC_Base_R_Forearm"),
           at("CC_Base_L_Hand"),      at("CC_Base_R_Hand")}}});
    // Bandai Namco Research Motion Dataset (Hips, Spine, Chest, Neck, Head; *_L / *_R limbs; Toes_*).
    maps.push_back(
        {"bandai_namco",
         0.01,
         PositionChannels::replace_offset,
         false,
         {{at("Hips"),       at("UpperLeg_L"), at("UpperLeg_R"), at("Spine"),      at("LowerLeg_L"),
           at("LowerLeg_R"), at("Chest"),      at("Foot_L"),     at("Foot_R"),     between("Chest", "Neck", 0.25),
           at("Toes_L"),     at("Toes_R"),     at("Neck"),       at("Shoulder_L"), at("Shoulder_R"),
           at("Head"),       at("UpperArm_L"), at("UpperArm_R"), at("LowerArm_L"), at("LowerArm_R"),
           at("Hand_L"),     at("Hand_R")}}});
    // HDM05 (and CMU) ASF/AMC, CMU-style bone names. asf_amc.hpp holds each bone as a joint at the bone's start,
    // so "lfemur" is the hip, "ltibia" the knee, "lfoot" the ankle and "ltoes" the toe base. The length unit
    // comes from the ASF file.
    maps.push_back({"hdm05_asf_amc",
                    0.0254 / 0.45,
                    PositionChannels::replace_offset,
                    false,
                    {{at("root"),
                      at("lfemur"),
                      at("rfemur"),
                      between("lowerback", "upperback", 0.5),
                      at("ltibia"),
                      at("rtibia"),
                      at("upperback"),
                      at("lfoot"),
                      at("rfoot"),
                      at("thorax"),
                      at("ltoes"),
                      at("rtoes"),
                      at("lowerneck"),
                      between("lclavicle", "lhumerus", 0.4),
                      between("rclavicle", "rhumerus", 0.4),
                      at("head"),
                      at("lhumerus"),
                      at("rhumerus"),
                      at("lradius"),
                      at("rradius"),
                      at("lwrist"),
                      at("rwrist")}}});
    // ReActIdle (Blender Rigify names, metres): the spine is pelvis -> spine (at the pelvis) -> spine.001 -> neck,
    // so SMPL's spine1 and spine3 sit on those segments; the collar is the shoulder bone's pivot (at the neck
    // base): ReActIdle's shoulder bones rotate (shrugs), and only their pivot keeps both the spine3 -> collar and
    // the collar -> shoulder lengths constant (a point along the bone, as for HDM05, drifts by 5 mm); wrists and
    // toes are End Sites. Only the root's
    // position channels count, added to its OFFSET: replacing the OFFSET would put the pelvis at the floor and the
    // feet 0.67 m below it, and the other joints' channels repeat their OFFSET (bvh.hpp).
    maps.push_back({"reactidle_rigify",
                    1.0,
                    PositionChannels::root_only,
                    false,
                    {{at("pelvis"),        at("thigh.L"),
                      at("thigh.R"),       between("spine", "spine.001", 0.5),
                      at("shin.L"),        at("shin.R"),
                      at("spine.001"),     at("foot.L"),
                      at("foot.R"),        between("spine.001", "neck", 0.25),
                      at("foot.L/end"),    at("foot.R/end"),
                      at("neck"),          at("shoulder.L"),
                      at("shoulder.R"),    at("face"),
                      at("upper_arm.L"),   at("upper_arm.R"),
                      at("forearm.L"),     at("forearm.R"),
                      at("forearm.L/end"), at("forearm.R/end")}}});
    // t2imu's own export (bvh_export.hpp): HumanML3D's joint names, centimetres.
    SkeletonMap own{"t2imu_smpl22", 0.01, PositionChannels::replace_offset, false, {}};
    for (size_t j = 0; j < 22; ++j) own.joints[j] = at(smpl22::kJointNames[j]);
    maps.push_back(own);
    return maps;
}

std::vector<std::string> missing_joints(const SkeletonMap& map, const std::vector<std::string>& names) {
    auto has = [&](const std::string& n) {
        return n.empty() || std::find(names.begin(), names.end(), n) != names.end();
    };
    std::vector<std::string> missing;
    for (size_t j = 0; j < map.joints.size(); ++j)
        if (!has(map.joints[j].from) || !has(map.joints[j].to)) missing.push_back(smpl22::kJointNames[j]);
    return missing;
}

}  // namespace

const std::vector<SkeletonMap>& skeleton_maps() {
    static const std::vector<SkeletonMap> maps = make_maps();
    return maps;
}

const SkeletonMap& find_skeleton_map(const std::vector<std::string>& names, const std::string& source) {
    const SkeletonMap* closest = nullptr;
    std::vector<std::string> closest_missing;
    for (const SkeletonMap& map : skeleton_maps()) {
        const std::vector<std::string> missing = missing_joints(map, names);
        if (missing.empty()) return map;
        if (!closest || missing.size() < closest_missing.size()) {
            closest = &map;
            closest_missing = missing;
        }
    }
    std::string list;
    for (const std::string& m : closest_missing) list += (list.empty() ? "" : ", ") + m;
    throw Error(source, "skeleton",
                "a known skeleton flavour (cgspeed_daz, iclone_cc_base, bandai_namco, hdm05_asf_amc, reactidle_rigify, "
                "t2imu_smpl22)",
                "no joint for SMPL " + list + " (closest: " + closest->flavour + ")");
}

}  // namespace t2imu
