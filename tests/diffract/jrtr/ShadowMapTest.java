package diffract.jrtr;

import com.jogamp.opengl.GLAutoDrawable;
import diffract.jrtr.scenegraph.Group;
import diffract.jrtr.scenegraph.RenderList;
import diffract.jrtr.scenegraph.ShapeNode;
import diffract.jrtr.scenegraph.Shapes;
import diffract.jrtr.scenegraph.TransformGroup;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

import javax.vecmath.Matrix4f;
import javax.vecmath.Vector3f;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A shadow map is drawn again only when what it shows changes: frames of a still scene reuse it; turning the light or
 * moving a caster draws it anew, and its depth bounds follow.
 */
@Tag("gl")
class ShadowMapTest {
    @Test
    void aStillSceneDrawsItsMapOnceAndAChangeDrawsItAgain() {
        GlTestSupport.assumeOffscreenGl();
        ShadowMap map = new ShadowMap(64);
        TransformGroup caster = new TransformGroup("caster").add(new ShapeNode(Shapes.cube(0.5f),
                GlTestSupport.unlit(1, 1, 1)));
        Vector3f towardsLight = new Vector3f(0.2f, 1, 0.1f);
        Renderer renderer = new Renderer(new Group("root"), GlTestSupport.unitCamera(),
                GlTestSupport.rightAngleFrustum()) {
            @Override
            public void display(GLAutoDrawable drawable) {
                map.aim(towardsLight, new Vector3f(0, 0, 0), 1, 0.1f);
                map.render(context(), RenderList.collect(caster));
                super.display(drawable);
            }
        };
        try (OffscreenTarget target = new OffscreenTarget(renderer)) {
            target.renderRgba(8, 8);
            target.renderRgba(8, 8);
            target.renderRgba(8, 8);
            assertEquals(1, map.passes(), "three frames of a still scene");
            float nearest = map.depthBounds().bounds(map.depthBounds().levelCount() - 1, 0, 0)[0];
            towardsLight.set(-0.3f, 1, 0.1f);
            target.renderRgba(8, 8);
            assertEquals(2, map.passes(), "the light turned");
            Matrix4f lifted = new Matrix4f();
            lifted.setIdentity();
            lifted.setTranslation(new Vector3f(0, 0.4f, 0));
            caster.setTransform(lifted);
            target.renderRgba(8, 8);
            target.renderRgba(8, 8);
            assertEquals(3, map.passes(), "the caster moved, then stood still");
            float liftedNearest = map.depthBounds().bounds(map.depthBounds().levelCount() - 1, 0, 0)[0];
            assertTrue(liftedNearest < nearest, "the lifted cube is nearer the light: " + liftedNearest + " < "
                    + nearest);
        }
    }
}
