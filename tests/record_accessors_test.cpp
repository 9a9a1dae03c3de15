// Tests that each buffer record's constructor (layout.h, lights.h) puts every value where its
// named accessor reads it, so the host packs what the stages read.
#include <gtest/gtest.h>

#include "shaders/common/lights.h"

namespace {

using namespace wp::gpu;

TEST(RecordAccessors, Triangle) {
  GpuTriangle t = makeGpuTriangle(vec3(1, 2, 3), vec3(2, 4, 6), vec3(0, 1, 5), 9u, 4u);
  EXPECT_EQ(triangleVertex0(t), vec3(1, 2, 3));
  EXPECT_EQ(triangleEdge1(t), vec3(1, 2, 3));
  EXPECT_EQ(triangleEdge2(t), vec3(-1, -1, 2));
  EXPECT_EQ(triangleMaterial(t), 9u);
  EXPECT_EQ(triangleEmitter(t), 4u);
  EXPECT_FALSE(triangleAlphaTested(t));
  EXPECT_TRUE(triangleAlphaTested(withTriangleAlphaTested(t, true)));
}

TEST(RecordAccessors, TriangleShading) {
  GpuTriangleShading s = makeGpuTriangleShading(
      vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, 0, 1), vec2(0.1f, 0.2f), vec2(0.3f, 0.4f), vec2(0.5f, 0.6f), true,
      0x11223344u, 0x55667788u, 0x99aabbccu, vec4(0, 1, 0, -1), vec4(0, 0, 1, 1), vec4(1, 0, 0, -1));
  EXPECT_EQ(vertexNormal0(s), vec3(1, 0, 0));
  EXPECT_EQ(vertexNormal1(s), vec3(0, 1, 0));
  EXPECT_EQ(vertexNormal2(s), vec3(0, 0, 1));
  EXPECT_EQ(vertexUv0(s), vec2(0.1f, 0.2f));
  EXPECT_EQ(vertexUv1(s), vec2(0.3f, 0.4f));
  EXPECT_EQ(vertexUv2(s), vec2(0.5f, 0.6f));
  EXPECT_TRUE(hasUv(s));
  EXPECT_EQ(vertexColor0(s), 0x11223344u);
  EXPECT_EQ(vertexColor1(s), 0x55667788u);
  EXPECT_EQ(vertexColor2(s), 0x99aabbccu);
  EXPECT_EQ(vertexTangent0(s), vec4(0, 1, 0, -1));
  EXPECT_EQ(vertexTangent1(s), vec4(0, 0, 1, 1));
  EXPECT_EQ(vertexTangent2(s), vec4(1, 0, 0, -1));
  EXPECT_FALSE(hasTexCoord1(s));
  GpuTriangleShading withSet1 = withTexCoord1(s, vec2(0.7f, 0.8f), vec2(0.9f, 1.0f), vec2(1.1f, 1.2f));
  EXPECT_TRUE(hasTexCoord1(withSet1));
  EXPECT_EQ(vertexTexCoord1At0(withSet1), vec2(0.7f, 0.8f));
  EXPECT_EQ(vertexTexCoord1At1(withSet1), vec2(0.9f, 1.0f));
  EXPECT_EQ(vertexTexCoord1At2(withSet1), vec2(1.1f, 1.2f));
  EXPECT_EQ(vertexUv2(withSet1), vec2(0.5f, 0.6f));
  EXPECT_FALSE(hasUv(makeGpuTriangleShading(vec3(0), vec3(0), vec3(0), vec2(0), vec2(0), vec2(0), false, 0u, 0u, 0u,
                                            vec4(0), vec4(0), vec4(0))));
}

TEST(RecordAccessors, Texture) {
  GpuTexture t = makeGpuTexture(100u, 16u, 8u, WP_TEXTURE_WRAP_MIRROR, WP_TEXTURE_WRAP_CLAMP, true, false);
  EXPECT_EQ(textureFirstTexel(t), 100u);
  EXPECT_EQ(textureWidth(t), 16u);
  EXPECT_EQ(textureHeight(t), 8u);
  EXPECT_EQ(textureWrapS(t), WP_TEXTURE_WRAP_MIRROR);
  EXPECT_EQ(textureWrapT(t), WP_TEXTURE_WRAP_CLAMP);
  EXPECT_TRUE(textureIsSrgb(t));
  EXPECT_FALSE(textureIsNearest(t));
  EXPECT_TRUE(textureIsNearest(makeGpuTexture(0u, 1u, 1u, 0u, 0u, false, true)));
  EXPECT_FALSE(textureUsesTexCoord1(t));
  EXPECT_EQ(textureUvTransformU(t), vec3(1, 0, 0));
  EXPECT_EQ(textureUvTransformV(t), vec3(0, 1, 0));
  GpuTexture slot = withTexCoords(t, true, vec3(2, 0, 0.5f), vec3(0, 3, 0.25f));
  EXPECT_TRUE(textureUsesTexCoord1(slot));
  EXPECT_TRUE(textureIsSrgb(slot));
  EXPECT_EQ(textureWrapS(slot), WP_TEXTURE_WRAP_MIRROR);
  EXPECT_EQ(textureUvTransformU(slot), vec3(2, 0, 0.5f));
  EXPECT_EQ(textureUvTransformV(slot), vec3(0, 3, 0.25f));
}

TEST(RecordAccessors, InstanceAndMotionKeys) {
  GpuInstance inst = makeGpuInstance(vec4(1, 0, 0, 5), vec4(0, 1, 0, 6), vec4(0, 0, 1, 7), WP_INSTANCE_MESH, 12u);
  EXPECT_EQ(instanceKind(inst), WP_INSTANCE_MESH);
  EXPECT_EQ(instanceBvhRoot(inst), 12u);
  EXPECT_EQ(instanceFirstLight(inst), WP_INVALID);
  EXPECT_EQ(instanceMotionKeys(inst), WP_INVALID);
  EXPECT_EQ(pointToObject(inst, vec3(0, 0, 0)), vec3(5, 6, 7));
  inst = withInstanceMotionKeys(withInstanceFirstLight(inst, 3u), 20u);
  EXPECT_EQ(instanceFirstLight(inst), 3u);
  EXPECT_EQ(instanceMotionKeys(inst), 20u);
  EXPECT_EQ(instanceSphereMaterial(makeGpuInstance(vec4(0), vec4(0), vec4(0), WP_INSTANCE_SPHERE, 2u)), 2u);

  GpuInstance trs = makeTrsMotionKey(vec3(1, 2, 3), vec4(0, 0, 0.6f, 0.8f), vec3(4, 5, 6));
  EXPECT_EQ(motionKeyKind(trs), WP_MOTION_KEY_TRS);
  EXPECT_EQ(vec3(motionKeyTranslation(trs)), vec3(1, 2, 3));
  EXPECT_EQ(motionKeyRotation(trs), vec4(0, 0, 0.6f, 0.8f));
  EXPECT_EQ(vec3(motionKeyScale(trs)), vec3(4, 5, 6));
  GpuInstance matrix = makeMatrixMotionKey(vec4(1, 2, 3, 4), vec4(5, 6, 7, 8), vec4(9, 10, 11, 12));
  EXPECT_EQ(motionKeyKind(matrix), WP_MOTION_KEY_MATRIX);
  EXPECT_EQ(motionKeyRow0(matrix), vec4(1, 2, 3, 4));
  EXPECT_EQ(motionKeyRow1(matrix), vec4(5, 6, 7, 8));
  EXPECT_EQ(motionKeyRow2(matrix), vec4(9, 10, 11, 12));
}

TEST(RecordAccessors, Plane) {
  GpuPlane p = makeGpuPlane(vec3(0, 1, 0), -2.5f, 6u);
  EXPECT_EQ(planeNormal(p), vec3(0, 1, 0));
  EXPECT_EQ(planeDistance(p), -2.5f);
  EXPECT_EQ(planeMaterial(p), 6u);
}

TEST(RecordAccessors, ShadowRay) {
  ShadowRay s = makeShadowRay(vec3(1, 2, 3), 42u, vec3(0, 0, 1), 7.5f, vec3(0.25f, 0.5f, 2), 0.75f);
  EXPECT_EQ(shadowRayOrigin(s), vec3(1, 2, 3));
  EXPECT_EQ(shadowRayPathSlot(s), 42u);
  EXPECT_EQ(shadowRayDirection(s), vec3(0, 0, 1));
  EXPECT_EQ(shadowRayLength(s), 7.5f);
  EXPECT_EQ(shadowRayContribution(s), vec3(0.25f, 0.5f, 2));
  EXPECT_EQ(shadowRayTime(s), 0.75f);
}

TEST(RecordAccessors, TriangleLight) {
  GpuLight l = makeTriangleLight(vec3(1, 2, 3), vec3(2, 2, 3), vec3(1, 4, 3), 1.0f, vec3(5, 6, 7), 0.5f, true, 11u,
                                 WP_INVALID);
  EXPECT_EQ(lightKind(l), WP_LIGHT_TRIANGLE);
  EXPECT_TRUE(lightIsDoubleSided(l));
  EXPECT_EQ(triangleLightVertex(l), vec3(1, 2, 3));
  EXPECT_EQ(triangleLightEdge1(l), vec3(1, 0, 0));
  EXPECT_EQ(triangleLightEdge2(l), vec3(0, 2, 0));
  EXPECT_EQ(triangleLightArea(l), 1.0f);
  EXPECT_EQ(lightEmission(l), vec3(5, 6, 7));
  EXPECT_EQ(lightSelectionWeight(l), 0.5f);
  EXPECT_EQ(triangleLightShading(l), 11u);
  EXPECT_EQ(triangleLightTexture(l), WP_INVALID);
  EXPECT_FALSE(lightIsDoubleSided(
      makeTriangleLight(vec3(0), vec3(1, 0, 0), vec3(0, 1, 0), 0.5f, vec3(1), 1.0f, false, 0u, WP_INVALID)));

  l = withAliasEntry(withPowerProbability(l, 0.125f), 0.75f, 3u);
  EXPECT_EQ(lightPowerProbability(l), 0.125f);
  EXPECT_EQ(lightAliasThreshold(l), 0.75f);
  EXPECT_EQ(lightAlias(l), 3u);
  EXPECT_EQ(triangleLightVertex(l), vec3(1, 2, 3));  // the alias table leaves the geometry alone
  EXPECT_EQ(triangleLightArea(l), 1.0f);
  EXPECT_EQ(lightSelectionWeight(l), 0.5f);
}

TEST(RecordAccessors, PunctualLight) {
  GpuLight l = makePunctualLight(WP_LIGHT_SPOT, vec3(1, 2, 3), vec3(4, 5, 6), vec3(0, -1, 0), vec3(0, 0, -1), 0.5f,
                                 0.75f, vec3(8, 9, 10), 3.0f);
  EXPECT_EQ(lightKind(l), WP_LIGHT_SPOT);
  EXPECT_EQ(punctualPositionAtOpen(l), vec3(1, 2, 3));
  EXPECT_EQ(punctualPositionAtClose(l), vec3(4, 5, 6));
  EXPECT_EQ(punctualDirectionAtOpen(l), vec3(0, -1, 0));
  EXPECT_EQ(punctualDirectionAtClose(l), vec3(0, 0, -1));
  EXPECT_EQ(spotCosOuter(l), 0.5f);
  EXPECT_EQ(spotCosInner(l), 0.75f);
  EXPECT_EQ(lightEmission(l), vec3(8, 9, 10));
  EXPECT_EQ(lightSelectionWeight(l), 3.0f);
  EXPECT_EQ(punctualPosition(l, 0.5f), vec3(2.5f, 3.5f, 4.5f));
}

}  // namespace
