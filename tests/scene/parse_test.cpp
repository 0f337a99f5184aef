// Parser tests from strings: every command, defaults, the transform stack, doc/scene-format.md, "File structure".
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/parse.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

TEST(Parse, Defaults) {
  SceneDesc s = parseBody("sphere 0 0 0 1\n");
  EXPECT_EQ(s.width, 64);
  EXPECT_EQ(s.height, 48);
  EXPECT_EQ(s.maxDepth, 5);
  EXPECT_EQ(s.output, "raytrace.png");
  EXPECT_EQ(s.outputLine, 0);
  ASSERT_EQ(s.materials.size(), 1u);
  expectNear(s.materials[0].ambient, dvec3(0.2));
  expectNear(s.materials[0].diffuse, dvec3(0.0));
  expectNear(s.materials[0].specular, dvec3(0.0));
  expectNear(s.materials[0].emission, dvec3(0.0));
  EXPECT_EQ(s.materials[0].shininess, 0.0);
}

TEST(Parse, GeneralCommandsAndCamera) {
  SceneDesc s = parseScene("size 640 480\nmaxdepth 3\noutput out/img.png\ncamera 1 2 3 4 5 6 0 0 1 30\n", "t");
  EXPECT_EQ(s.maxDepth, 3);
  EXPECT_EQ(s.output, "out/img.png");
  EXPECT_EQ(s.outputLine, 3);
  expectNear(s.camera.from, {1, 2, 3});
  expectNear(s.camera.at, {4, 5, 6});
  expectNear(s.camera.up, {0, 0, 1});
  EXPECT_EQ(s.camera.fovyDegrees, 30.0);
}

TEST(Parse, FileRulesOfSection1) {
  // Trailing spaces, '+', exponent, CRLF, tabs, comments with leading blanks, blank lines,
  // a trailing comment, and no final newline.
  std::string text =
      "size 32 16   \r\n"
      "\r\n"
      "   # a comment\r\n"
      "camera\t0 0 +5\t0 0 0 0 1 0 45\r\n"
      "vertex +1 -1 0   \r\n"
      "vertex 1e-3 2.5E+1 -.5\r\n"
      "vertex 0 0 0 # trailing comment\r\n"
      "tri 0 1 2";
  SceneDesc s = parseScene(text, "t");
  EXPECT_EQ(s.width, 32);
  EXPECT_EQ(s.height, 16);
  ASSERT_EQ(s.triangles.size(), 1u);
  expectNear(s.triangles[0].p[0], {1, -1, 0});
  expectNear(s.triangles[0].p[1], {1e-3, 25, -0.5});
  expectNear(s.camera.from, {0, 0, 5});
}

TEST(Parse, MaterialsAreCapturedPerObject) {
  SceneDesc s = parseBody(
      "ambient 0.1 0.2 0.3\ndiffuse 1 0 0\nspecular 0 1 0\nemission 0 0 1\nshininess 7\nsphere 0 0 0 1\n"
      "sphere 1 0 0 1\n"
      "diffuse 0 0.5 0\nsphere 2 0 0 1\n");
  ASSERT_EQ(s.spheres.size(), 3u);
  ASSERT_EQ(s.materials.size(), 2u);   // consecutive objects with equal materials share one
  EXPECT_EQ(s.spheres[0].material, s.spheres[1].material);
  const Material& m = s.materials[s.spheres[0].material];
  expectNear(m.ambient, {0.1, 0.2, 0.3});
  expectNear(m.diffuse, {1, 0, 0});
  expectNear(m.specular, {0, 1, 0});
  expectNear(m.emission, {0, 0, 1});
  EXPECT_EQ(m.shininess, 7.0);
  expectNear(s.materials[s.spheres[2].material].diffuse, {0, 0.5, 0});
  expectNear(s.materials[s.spheres[2].material].ambient, {0.1, 0.2, 0.3});
}

TEST(Parse, TransformsRightMultiplyInFileOrder) {
  // translate then scale: p' = T * S * p.
  SceneDesc s = parseBody("vertex 1 1 1\ntranslate 10 0 0\nscale 2 3 4\ntri 0 0 0\n");
  expectNear(s.triangles[0].p[0], {12, 3, 4});
}

TEST(Parse, RotateIsRightHandedDegreesAndNormalisesTheAxis) {
  SceneDesc s = parseBody("vertex 1 0 0\nrotate 0 0 5 90\ntri 0 0 0\n");
  expectNear(s.triangles[0].p[0], {0, 1, 0});
}

TEST(Parse, PushAndPopRestoreTheTransform) {
  SceneDesc s = parseBody(
      "vertex 0 0 0\ntranslate 1 0 0\npushTransform\ntranslate 0 1 0\ntri 0 0 0\npopTransform\ntri 0 0 0\n"
      "pushTransform\npushTransform\n");   // unbalanced pushes at the end are valid
  ASSERT_EQ(s.triangles.size(), 2u);
  expectNear(s.triangles[0].p[0], {1, 1, 0});
  expectNear(s.triangles[1].p[0], {1, 0, 0});
}

TEST(Parse, SphereKeepsItsTransformAndInverse) {
  SceneDesc s = parseBody("translate 1 2 3\nscale 2 1 1\nsphere 0.5 0 0 0.25\n");
  ASSERT_EQ(s.spheres.size(), 1u);
  const Sphere& sp = s.spheres[0];
  expectNear(sp.center, {0.5, 0, 0});
  EXPECT_EQ(sp.radius, 0.25);
  dmat4 expected = glm::scale(glm::translate(dmat4(1.0), dvec3(1, 2, 3)), dvec3(2, 1, 1));
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) {
      EXPECT_NEAR(sp.worldFromObject[c][r], expected[c][r], 1e-12);
      EXPECT_NEAR((sp.worldFromObject * sp.objectFromWorld)[c][r], c == r ? 1.0 : 0.0, 1e-12);
    }
}

TEST(Parse, TriNormalTransformsNormalsWithTheInverseTranspose) {
  // Scaling x by 2 turns the normal (1,1,0)/sqrt2 into (1,2,0)/sqrt5 (inverse transpose).
  SceneDesc s = parseBody(
      "maxvertnorms 3\nvertexnormal 0 0 0 1 1 0\nvertexnormal 1 0 0 1 1 0\nvertexnormal 0 1 0 1 1 0\n"
      "scale 2 1 1\ntrinormal 0 1 2\n");
  ASSERT_EQ(s.triangles.size(), 1u);
  const Triangle& t = s.triangles[0];
  EXPECT_TRUE(t.smooth);
  expectNear(t.p[1], {2, 0, 0});
  expectNear(t.n[0], dvec3(1, 2, 0) / std::sqrt(5.0));
}

TEST(Parse, TriUsesVertexListAndTriNormalUsesItsOwn) {
  SceneDesc s = parseBody(
      "maxverts 3\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nvertexnormal 5 5 5 0 0 1\n"
      "vertexnormal 6 5 5 0 0 1\nvertexnormal 5 6 5 0 0 1\ntri 0 1 2\ntrinormal 0 1 2\n");
  ASSERT_EQ(s.triangles.size(), 2u);
  EXPECT_FALSE(s.triangles[0].smooth);
  expectNear(s.triangles[0].p[2], {0, 1, 0});
  expectNear(s.triangles[1].p[2], {5, 6, 5});
}

TEST(Parse, LightsAreTransformedAndKeepTheirAttenuation) {
  SceneDesc s = parseBody(
      "point 1 0 0 1 1 1\nattenuation 1 0.5 0.25\ntranslate 0 10 0\nrotate 0 0 1 90\n"
      "point 1 0 0 0.5 0.5 0.5\ndirectional 1 0 0 0.2 0.3 0.4\n");
  ASSERT_EQ(s.lights.size(), 3u);
  EXPECT_EQ(s.lights[0].type, LightType::Point);
  expectNear(s.lights[0].vec, {1, 0, 0});
  expectNear(s.lights[0].attenuation, {1, 0, 0});
  expectNear(s.lights[1].vec, {0, 11, 0});       // point: rotated, then translated
  expectNear(s.lights[1].attenuation, {1, 0.5, 0.25});
  EXPECT_EQ(s.lights[2].type, LightType::Directional);
  expectNear(s.lights[2].vec, {0, 1, 0});        // direction: rotated only
  expectNear(s.lights[2].color, {0.2, 0.3, 0.4});
}

TEST(Parse, LaterCameraWins) {
  SceneDesc s = parseBody("camera 0 0 9 0 0 0 0 1 0 60\n");
  expectNear(s.camera.from, {0, 0, 9});
  EXPECT_EQ(s.camera.fovyDegrees, 60.0);
}

TEST(Parse, UpNeedNotBePerpendicular) {
  SceneDesc s = parseScene("size 4 4\ncamera 0 -4 4 0 -1 0 0 1 1 45\n", "t");
  EXPECT_EQ(s.camera.up, dvec3(0, 1, 1));
}
